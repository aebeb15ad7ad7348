#include "biphasic/assembly/threads.hpp"

#include <omp.h>

#include <cstdlib>

namespace biphasic {

int worker_threads() {
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    const int n = std::atoi(env);
    if (n > 0) return n;
  }
  return omp_get_num_procs();
}

}  // namespace biphasic
