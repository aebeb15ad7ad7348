#include "biphasic/parallel/collective_failure.hpp"

#include <exception>
#include <stdexcept>
#include <string>

#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

void run_collectively(MPI_Comm comm, const std::function<void()>& work) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::string message;
  int kind = 0;  // 0 none, 1 recoverable (InvertedElement), 2 other, 3 bad input
  try {
    work();
  } catch (const InvertedElement& e) {
    kind = 1;
    message = e.what();
  } catch (const std::invalid_argument& e) {
    kind = 3;
    message = e.what();
  } catch (const std::exception& e) {
    kind = 2;
    message = e.what();
  } catch (...) {
    kind = 2;
    message = "unknown exception";
  }
  // The lowest failing rank speaks for all.
  const int mine = kind ? rank : size;
  int speaker = size;
  MPI_Allreduce(&mine, &speaker, 1, MPI_INT, MPI_MIN, comm);
  if (speaker == size) return;
  int header[2] = {kind, static_cast<int>(message.size())};
  MPI_Bcast(header, 2, MPI_INT, speaker, comm);
  message.resize(static_cast<std::size_t>(header[1]));
  MPI_Bcast(message.data(), header[1], MPI_CHAR, speaker, comm);
  if (size > 1) message = "process " + std::to_string(speaker) + ": " + message;
  if (header[0] == 1) throw InvertedElement(message);
  if (header[0] == 3) throw std::invalid_argument(message);
  throw std::runtime_error(message);
}

std::string broadcast_string(std::string text, int root, MPI_Comm comm) {
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, root, comm);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, root, comm);
  return text;
}

}  // namespace biphasic
