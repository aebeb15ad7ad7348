// Preloaded (LD_PRELOAD) into an MPI run by exit_inside_library_ends_every_process.py: on the
// process whose rank is BIPHASIC_TEST_EXIT_RANK, MUMPS' analysis (JOB = 1) ends the process
// through exit(2), as a Fortran runtime error inside MUMPS does; every other call goes on to
// the real MUMPS.
#include <dlfcn.h>
#include <dmumps_c.h>
#include <smumps_c.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

bool this_process_exits() {
  const char* chosen = std::getenv("BIPHASIC_TEST_EXIT_RANK");
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  return chosen && rank && std::strcmp(chosen, rank) == 0;
}

template <class Struc>
void call_or_exit(const char* name, Struc* id) {
  if (id->job == 1 && this_process_exits()) {
    std::fprintf(stderr, "exit_in_library: process %s exits inside %s (JOB = 1)\n",
                 std::getenv("OMPI_COMM_WORLD_RANK"), name);
    std::exit(2);
  }
  using Real = void (*)(Struc*);
  auto real = reinterpret_cast<Real>(dlsym(RTLD_NEXT, name));
  if (!real) {
    std::fprintf(stderr, "exit_in_library: %s not found\n", name);
    std::abort();
  }
  real(id);
}

}  // namespace

extern "C" void dmumps_c(DMUMPS_STRUC_C* id) { call_or_exit("dmumps_c", id); }
extern "C" void smumps_c(SMUMPS_STRUC_C* id) { call_or_exit("smumps_c", id); }
