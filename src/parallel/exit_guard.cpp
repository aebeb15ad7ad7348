// Abort every process when one ends through exit() outside the program's own error handling.
#include "biphasic/parallel/exit_guard.hpp"

#include <hdf5.h>

#include <cstdio>
#include <cstdlib>

namespace biphasic {
namespace {

MPI_Comm guarded_comm = MPI_COMM_NULL;
bool armed = false;
bool registered = false;

void abort_every_process() {
  if (!armed) return;
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  int rank = 0;
  MPI_Comm_rank(guarded_comm, &rank);
  std::fprintf(stderr,
               "error: process %d ended inside a library call (its message, if any, is above); "
               "ending every process\n",
               rank);
  std::fflush(stderr);
  MPI_Abort(guarded_comm, 3);
}

}  // namespace

void arm_exit_guard(MPI_Comm comm) {
  // Exit handlers run last-registered first: HDF5 registers its own when it is initialised,
  // and that one waits for the other processes when a parallel file is open.
  H5open();
  guarded_comm = comm;
  if (!registered) registered = std::atexit(abort_every_process) == 0;
  armed = registered;
}

void disarm_exit_guard() { armed = false; }

}  // namespace biphasic
