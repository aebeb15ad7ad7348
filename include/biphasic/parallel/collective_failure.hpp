// A failure on one process must end the work of all: otherwise the others wait forever in the
// next collective call. run_collectively runs a piece of local work on every process and, if
// it threw on any, throws on every process, with the message of the lowest failing rank.
#pragma once

#include <mpi.h>

#include <functional>

namespace biphasic {

/// Runs `work` on this process; collective over `comm`. If `work` threw on any process, every
/// process throws: InvertedElement if that rank's exception was one (a recoverable state for
/// the integrators), std::invalid_argument if it was one (bad input), else std::runtime_error; the
/// message is prefixed with "process <rank>: " when the communicator has more than one process.
void run_collectively(MPI_Comm comm, const std::function<void()>& work);

}  // namespace biphasic
