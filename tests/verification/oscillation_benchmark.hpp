// First backward-Euler step after a step load on a column of cubic cells
// (cases/verification/oscillation): the pressure overshoot above the load q against
// r = c Δt / h², for each stabilisation.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "verification_support.hpp"

namespace biphasic::verification {

/// Overshoot (max p − q)/q after the first step [-].
struct FirstStepOvershoot {
  double vertices = 0.0;    ///< max over every vertex of the column
  double level_mean = 0.0;  ///< max over the layers' mean vertex pressure (the 1D-like part)
  /// The oscillation measure of the line measures (biphasic/study/measures.hpp) along the edge
  /// x = y = 0 from the bottom to the drained top: non-monotonicity over p_mid [-].
  double line_oscillation = 0.0;
};

struct OscillationSweep {
  std::vector<double> r;  ///< c Δt / h², increasing
  /// By stabilisation.type ("none", "gls", "flux_perturbation"), one entry per r.
  std::map<std::string, std::vector<FirstStepOvershoot>> overshoot;
  /// By stabilisation.type: the r above which the vertex overshoot stays below 1e-3, located by
  /// bisection between the sweep's values (to 1e-3 relative).
  std::map<std::string, double> threshold;
  /// The same for the layers' mean pressure.
  std::map<std::string, double> level_threshold;
};

/// One backward-Euler step of Δt = r h² / c (h = the layer thickness H/nz, c = k (λ + 2μ)) of
/// the column case `config` on `mesh`, from rest under the step load q.
FirstStepOvershoot first_step_overshoot(const Mesh& mesh, Config config, double r);

/// Runs the first step for each r and stabilisation on nz layers of cubic cells (h = H/nz).
/// When $BIPHASIC_VERIFICATION_OUT is set, writes oscillation/overshoot_nz<nz>.csv
/// (r, stabilisation, overshoot, level_mean_overshoot, line_oscillation) and
/// oscillation/thresholds_nz<nz>.csv (stabilisation, r_vanishes, r_vanishes_level_mean).
OscillationSweep sweep_first_step(int nz);

}  // namespace biphasic::verification
