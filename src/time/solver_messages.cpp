#include "biphasic/time/solver_messages.hpp"

#include <ida/ida.h>
#include <kinsol/kinsol.h>
#include <sundials/sundials_linearsolver.h>

#include <sstream>

namespace biphasic {

std::string kinsol_flag_message(int flag) {
  switch (flag) {
    case KIN_SUCCESS:
      return "converged (KIN_SUCCESS)";
    case KIN_INITIAL_GUESS_OK:
      return "the initial guess already met the tolerances (KIN_INITIAL_GUESS_OK)";
    case KIN_STEP_LT_STPTOL:
      return "the Newton steps became smaller than the step tolerance (KIN_STEP_LT_STPTOL)";
    case KIN_MEM_NULL:
    case KIN_NO_MALLOC:
    case KIN_CONTEXT_ERR:
      return "the nonlinear solver was not set up (KINSOL memory or context missing)";
    case KIN_ILL_INPUT:
      return "the nonlinear solver was given an invalid input (KIN_ILL_INPUT)";
    case KIN_MEM_FAIL:
      return "out of memory in the nonlinear solver (KIN_MEM_FAIL)";
    case KIN_LINESEARCH_NONCONV:
      return "the line search found no step that reduces the residual "
             "(KIN_LINESEARCH_NONCONV)";
    case KIN_MAXITER_REACHED:
      return "the Newton iteration did not converge within time.newton.max_iterations "
             "iterations (KIN_MAXITER_REACHED)";
    case KIN_MXNEWT_5X_EXCEEDED:
      return "five consecutive Newton steps of the maximum length: the iteration diverges "
             "(KIN_MXNEWT_5X_EXCEEDED)";
    case KIN_LINESEARCH_BCFAIL:
      return "the line search could not satisfy its sufficient-decrease condition "
             "(KIN_LINESEARCH_BCFAIL)";
    case KIN_LINSOLV_NO_RECOVERY:
      return "the linear solver failed and a fresh Jacobian did not help "
             "(KIN_LINSOLV_NO_RECOVERY)";
    case KIN_LINIT_FAIL:
      return "the linear solver could not be initialised (KIN_LINIT_FAIL)";
    case KIN_LSETUP_FAIL:
      return "the Jacobian could not be evaluated or factorised (singular matrix?) "
             "(KIN_LSETUP_FAIL)";
    case KIN_LSOLVE_FAIL:
      return "the linear solve with the factorised Jacobian failed (KIN_LSOLVE_FAIL)";
    case KIN_SYSFUNC_FAIL:
      return "the residual could not be evaluated (KIN_SYSFUNC_FAIL)";
    case KIN_FIRST_SYSFUNC_ERR:
      return "the residual could not be evaluated at the initial guess (KIN_FIRST_SYSFUNC_ERR)";
    case KIN_REPTD_SYSFUNC_ERR:
      return "the residual could not be evaluated, repeatedly, along the Newton steps "
             "(KIN_REPTD_SYSFUNC_ERR)";
    case KIN_VECTOROP_ERR:
      return "a vector operation failed in the nonlinear solver (KIN_VECTOROP_ERR)";
    default:
      return "the nonlinear solver stopped for a reason it does not name (KINSOL return " +
             std::to_string(flag) + ")";
  }
}

std::string linear_solver_flag_message(int flag) {
  switch (flag) {
    case SUNLS_SUCCESS:
      return "succeeded (SUNLS_SUCCESS)";
    case SUNLS_MEM_FAIL:
      return "out of memory in the linear solver (SUNLS_MEM_FAIL)";
    case SUNLS_ILL_INPUT:
    case SUNLS_MEM_NULL:
      return "the linear solver was given an invalid input (SUNLS_ILL_INPUT)";
    case SUNLS_PACKAGE_FAIL_REC:
    case SUNLS_LUFACT_FAIL:
      return "the factorisation found the matrix singular (a zero pivot): are all rigid-body "
             "modes constrained? (SUNLS_PACKAGE_FAIL_REC)";
    case SUNLS_PACKAGE_FAIL_UNREC:
      return "the sparse direct solver failed (SUNLS_PACKAGE_FAIL_UNREC)";
    case SUNLS_CONV_FAIL:
    case SUNLS_RES_REDUCED:
      return "the iterative solver did not reach its tolerance (SUNLS_CONV_FAIL)";
    case SUNLS_PSET_FAIL_REC:
    case SUNLS_PSET_FAIL_UNREC:
      return "the preconditioner could not be set up (SUNLS_PSET_FAIL)";
    default:
      return "the linear solver stopped for a reason it does not name (SUNLinearSolver return " +
             std::to_string(flag) + ")";
  }
}

std::string ida_flag_message(int flag, double h) {
  std::ostringstream reduced;
  reduced << "h reduced to " << h << " s";
  const std::string h_note = reduced.str();
  switch (flag) {
    case IDA_SUCCESS:
      return "step completed (IDA_SUCCESS)";
    case IDA_TSTOP_RETURN:
      return "stop time reached (IDA_TSTOP_RETURN)";
    case IDA_TOO_MUCH_WORK:
      return "more internal steps than time.bdf.max_steps before the next output "
             "(IDA_TOO_MUCH_WORK)";
    case IDA_TOO_MUCH_ACC:
      return "the tolerances are too small for double precision at this solution "
             "(IDA_TOO_MUCH_ACC)";
    case IDA_ERR_FAIL:
      return "the local error test failed repeatedly, or with the smallest step (" + h_note +
             "); the solution changes faster than the tolerances can follow (IDA_ERR_FAIL)";
    case IDA_CONV_FAIL:
      return "the Newton iteration failed to converge repeatedly (" + h_note + ") (IDA_CONV_FAIL)";
    case IDA_LINIT_FAIL:
      return "the linear solver could not be initialised (IDA_LINIT_FAIL)";
    case IDA_LSETUP_FAIL:
      return "the Jacobian could not be evaluated or factorised (singular matrix?) "
             "(IDA_LSETUP_FAIL)";
    case IDA_LSOLVE_FAIL:
      return "the linear solve with the factorised Jacobian failed (IDA_LSOLVE_FAIL)";
    case IDA_RES_FAIL:
      return "the residual could not be evaluated (IDA_RES_FAIL)";
    case IDA_REP_RES_ERR:
      return "the residual could not be evaluated, repeatedly, after step reductions (" + h_note +
             ") (IDA_REP_RES_ERR)";
    case IDA_RTFUNC_FAIL:
      return "a root function failed (IDA_RTFUNC_FAIL)";
    case IDA_CONSTR_FAIL:
      return "the solution could not be kept within its constraints (" + h_note +
             ") (IDA_CONSTR_FAIL)";
    case IDA_FIRST_RES_FAIL:
      return "the residual could not be evaluated at the first step (IDA_FIRST_RES_FAIL)";
    case IDA_LINESEARCH_FAIL:
      return "the line search of the initial-condition solver failed (IDA_LINESEARCH_FAIL)";
    case IDA_NO_RECOVERY:
      return "a recoverable residual or linear-solver failure could not be recovered from "
             "(IDA_NO_RECOVERY)";
    case IDA_NLS_INIT_FAIL:
      return "the nonlinear solver could not be initialised (IDA_NLS_INIT_FAIL)";
    case IDA_NLS_SETUP_FAIL:
      return "the nonlinear solver's set-up failed (IDA_NLS_SETUP_FAIL)";
    case IDA_NLS_FAIL:
      return "the nonlinear solver failed unrecoverably (IDA_NLS_FAIL)";
    case IDA_MEM_NULL:
    case IDA_NO_MALLOC:
    case IDA_CONTEXT_ERR:
      return "the integrator was not set up (IDA memory or context missing)";
    case IDA_MEM_FAIL:
      return "out of memory in the integrator (IDA_MEM_FAIL)";
    case IDA_ILL_INPUT:
      return "the integrator was given an invalid input, e.g. a step too small to advance t "
             "(" +
             h_note + ") (IDA_ILL_INPUT)";
    case IDA_BAD_EWT:
      return "an error weight became zero or negative: a tolerance of 0 on a vanishing "
             "component (IDA_BAD_EWT)";
    case IDA_BAD_K:
      return "a derivative of too high an order was requested (IDA_BAD_K)";
    case IDA_BAD_T:
      return "the solution was requested outside the last step (IDA_BAD_T)";
    case IDA_BAD_DKY:
      return "no vector was given for the interpolated solution (IDA_BAD_DKY)";
    case IDA_VECTOROP_ERR:
      return "a vector operation failed in the integrator (IDA_VECTOROP_ERR)";
    default:
      return "the integrator stopped for a reason it does not name (IDA return " +
             std::to_string(flag) + ")";
  }
}

}  // namespace biphasic
