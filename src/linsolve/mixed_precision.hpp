// The mixed-precision policy of the MUMPS solvers, in one process and on several: when a
// solution from single-precision factors, refined in double precision, is accurate enough, and
// when to factorise in double precision instead.
#pragma once

#include <algorithm>

#include "biphasic/linsolve/linear_solver.hpp"

namespace biphasic::detail {

/// Accuracy asked of a refined solution x of A x = b.
struct RefinementTarget {
  static constexpr double kBackwardError = 1e-6;  ///< componentwise (Oettli–Prager)
  static constexpr double kResidual = 1e-4;       ///< ‖b − A x‖∞ / ‖b‖∞
  static constexpr int kMaxSteps = 10;            ///< refinement steps per solve at most

  /// How far x is from both targets (≤ 1: accurate enough), from its componentwise backward
  /// error max_i |r_i| / (|A| |x| + |b|)_i, max_i |r_i| and max_i |b_i|. The residual target
  /// matters where |A| |x| ≫ |b| (cancellation, as in IDA's first steps with h ~ 1e-12 s): a
  /// small backward error then still allows a residual as large as b, and Newton would not
  /// converge on such corrections.
  static double excess(double backward, double residual_max, double b_max) {
    const double relative = b_max > 0.0 ? residual_max / b_max : 0.0;
    return std::max(backward / kBackwardError, relative / kResidual);
  }

  enum class Outcome { Accurate, NotAccurate, SolverFailed };
  /// Refines a solution until it meets the target: `correct()` applies one correction
  /// x ← x + LU⁻¹(b − A x) (false: the solve failed), `excess()` measures the current x. Stops
  /// after kMaxSteps, or when a step does not halve the excess (single precision is not enough
  /// there). Counts the steps in `stats`.
  template <class Correct, class Excess>
  static Outcome refine(Correct correct, Excess excess, LinearSolverStats& stats) {
    double error = excess();
    for (int k = 0; k < kMaxSteps && error > 1.0; ++k) {
      if (!correct()) return Outcome::SolverFailed;
      ++stats.refinement_steps;
      const double previous = error;
      error = excess();
      if (error > 0.5 * previous) break;  // stalled
    }
    return error <= 1.0 ? Outcome::Accurate : Outcome::NotAccurate;
  }
};

/// After a single-precision factorisation fails or its refinement stalls, the next few
/// factorisations are in double precision — 4, then twice as many after each further fallback,
/// up to 64 — before single precision is tried again: IDA's first steps (h ~ 1e-6 s) need
/// double precision, its later steps do not.
class PrecisionBackoff {
 public:
  static constexpr int kFirst = 4, kMax = 64;
  /// True when the next factorisation may be in single precision.
  bool single_due() const { return double_left_ == 0; }
  /// Counts a fallback in `stats` and schedules the double-precision factorisations.
  void fall_back(LinearSolverStats& stats) {
    ++stats.precision_fallbacks;
    double_left_ = backoff_;
    backoff_ = std::min(2 * backoff_, kMax);
  }
  /// One of the scheduled double-precision factorisations is done.
  void double_factorised() {
    if (double_left_ > 0) --double_left_;
  }

 private:
  int double_left_ = 0;
  int backoff_ = kFirst;
};

}  // namespace biphasic::detail
