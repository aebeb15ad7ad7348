#include "biphasic/assembly/threads.hpp"

#include <omp.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>

namespace biphasic {

int worker_threads_for(const char* omp_num_threads, int processors) {
  const int available = processors > 0 ? processors : 1;
  if (omp_num_threads == nullptr) return available;
  char* end = nullptr;
  errno = 0;
  const long requested = std::strtol(omp_num_threads, &end, 10);
  const long bound = static_cast<long>(kMaxThreadsPerProcessor) * available;
  if (errno == ERANGE && requested > 0) return static_cast<int>(bound);  // beyond long: clamped
  if (end == omp_num_threads || errno == ERANGE || requested <= 0) return available;
  return static_cast<int>(requested < bound ? requested : bound);
}

int worker_threads() {
  const char* env = std::getenv("OMP_NUM_THREADS");
  const int processors = omp_get_num_procs();
  const int threads = worker_threads_for(env, processors);
  if (env != nullptr) {
    char* end = nullptr;
    const long requested = std::strtol(env, &end, 10);
    if (requested > threads)
      std::fprintf(stderr,
                   "note: OMP_NUM_THREADS=%s is more than %d threads per processor on %d "
                   "processors; using %d threads\n",
                   env, kMaxThreadsPerProcessor, processors, threads);
  }
  omp_set_num_threads(threads);  // also the default of OpenMP regions without num_threads
  return threads;
}

}  // namespace biphasic
