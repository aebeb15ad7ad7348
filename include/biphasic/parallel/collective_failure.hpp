// A failure on one process must end the work of all: otherwise the others wait forever in the
// next collective call. run_collectively runs a piece of local work on every process and, if
// it threw on any, throws on every process, with the message of the lowest failing rank.
#pragma once

#include <mpi.h>

#include <functional>
#include <string>

namespace biphasic {

/// Runs `work` on this process; collective over `comm`. If `work` threw on any process, every
/// process throws: InvertedElement if that rank's exception was one (a recoverable state for
/// the integrators), std::invalid_argument if it was one (bad input), else std::runtime_error; the
/// message is prefixed with "process <rank>: " when the communicator has more than one process.
void run_collectively(MPI_Comm comm, const std::function<void()>& work);

/// Process `root`'s `text` on every process of `comm` (collective; the others' `text` is
/// ignored): a failure's message, or a path only process 0 knows.
std::string broadcast_string(std::string text, int root, MPI_Comm comm);

}  // namespace biphasic
