// A process of an MPI run that ends through exit() inside a library (a Fortran runtime error in
// MUMPS, a fatal message in a mesh reader) bypasses the program's collective error handling
// (collective_failure.hpp): the other processes would wait forever in their next collective
// call, and the exiting one in HDF5's exit-time close of its files, which is collective too. The
// guard turns such an exit into an abort of every process, with a message naming the process.
#pragma once

#include <mpi.h>

namespace biphasic {

/// From here until disarm_exit_guard(), an exit() of this process aborts every process of
/// `comm` (MPI_Abort, exit status 3) after printing which process ended. Initialises HDF5 first,
/// so that the guard runs before HDF5's own exit handler. Call once, after MPI is initialised.
void arm_exit_guard(MPI_Comm comm);

/// The program is ending by its own path (returning from main): exit() is no longer an abort.
void disarm_exit_guard();

}  // namespace biphasic
