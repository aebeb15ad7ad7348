// SUNDIALS return flags and exceptions caught in callbacks, turned into sentences for the
// failure messages of the integrators (the flag's name kept in parentheses).
#pragma once

#include <string>

namespace biphasic {

/// KINSOL's return flag (KINSol) as a sentence, e.g. "the Newton iteration did not converge in
/// time.newton.max_iterations iterations (KIN_MAXITER_REACHED)".
std::string kinsol_flag_message(int flag);

/// A SUNLinearSolver's return flag (setup or solve) as a sentence, e.g. "the factorisation found
/// the matrix singular (a zero pivot) … (SUNLS_PACKAGE_FAIL_REC)".
std::string linear_solver_flag_message(int flag);

/// IDA's return flag (IDASolve) as a sentence; `h` [s] is the step IDA last tried.
std::string ida_flag_message(int flag, double h);

/// What a SUNDIALS callback stores when its body threw: the exception's message, and whether
/// retrying with a smaller step may help (an inverted element) or not (anything else).
struct CallbackFailure {
  std::string message;
  bool recoverable = false;
  void clear() {
    message.clear();
    recoverable = false;
  }
  bool empty() const { return message.empty(); }
};

/// Runs `body` inside a SUNDIALS callback, where no exception may escape into C frames: 0 if it
/// returns, else the exception is stored in `failure` and the return is 1 (recoverable: an
/// InvertedElement) or -1 (unrecoverable: any other exception).
template <class Body>
int guarded_callback(CallbackFailure& failure, Body&& body) noexcept;

}  // namespace biphasic

#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

template <class Body>
int guarded_callback(CallbackFailure& failure, Body&& body) noexcept {
  try {
    body();
    return 0;
  } catch (const InvertedElement& e) {
    failure.message = e.what();
    failure.recoverable = true;
    return 1;
  } catch (const std::exception& e) {
    failure.message = e.what();
    failure.recoverable = false;
    return -1;
  } catch (...) {
    failure.message = "an exception of unknown type";
    failure.recoverable = false;
    return -1;
  }
}

}  // namespace biphasic
