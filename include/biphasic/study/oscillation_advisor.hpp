// Pre-run advice on the first-step pressure oscillation of the unstabilised P2/P1 method.
//
// Backward Euler overshoots next to a drained face on its first steps when
//   r = c Δt / h² < r*,   c = k (λ + 2μ)  [mm²/s]  (the consolidation coefficient),
// h [mm] the element size normal to the face (Vermeer & Verruijt 1981: r* = 1/6 in 1D). Here
// h_e = 3 V_e / A_f is the height of tetrahedron e over its face f on the drained boundary, the
// verdict uses the smallest r (the tallest element), and r* = kOscillationThreshold is
// calibrated for that h (docs/results.md, "Oscillation advisor").
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "biphasic/io/config.hpp"
#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// r* for h = height over the drained face: where the first-step overshoot (max p − q)/q over
/// every vertex crosses 1 % on the structured column of the oscillation benchmark (every height
/// equal: measured 0.329). On mesh 1 of the paper the overshoot on the axis crosses 1 % lower,
/// at r_min = 0.029 (r_median = 0.070), so this value errs on the side of a warning.
inline constexpr double kOscillationThreshold = 0.33;

/// One drained face (a boundary with a pressure condition).
struct DrainedFaceAdvice {
  std::string face;
  /// c = k(1) H_A of the face's material, the smallest over the tetrahedra on the face when
  /// they belong to regions of different materials (the most oscillation-prone) [mm²/s].
  double consolidation_coefficient = 0.0;
  long elements = 0;      ///< tetrahedra with a face on the boundary
  double h_min = 0.0;     ///< smallest height over the face [mm]
  double h_median = 0.0;  ///< [mm]
  double h_max = 0.0;     ///< largest height: sets the smallest r [mm]
  double r_min = 0.0;     ///< c Δt / h_max² [-]
  double r_median = 0.0;  ///< c Δt / h_median² [-]
  double threshold = kOscillationThreshold;
  bool in_regime = false;           ///< r_min < threshold
  std::vector<std::string> advice;  ///< remedies, or that a stabilisation is on
};

struct OscillationAdvice {
  double consolidation_coefficient = 0.0;  ///< c = k (λ + 2μ) of [material] [mm²/s]
  double first_step = 0.0;                 ///< Δt of the first step (BDF: a bound) [s]
  std::string first_step_source;           ///< "time.dt", "time.bdf.initial_step" or the IDA bound
  bool bdf = false;
  std::string stabilisation;  ///< "none", "gls", "flux_perturbation"
  std::vector<DrainedFaceAdvice> faces;
};

/// Heights h_e = 3 V_e / A_f [mm] of the tetrahedra with a face f on `boundary` (straight corner
/// geometry; a tetrahedron with several faces on it counts once, with its smallest height).
/// Throws std::runtime_error if the boundary does not exist or a face belongs to no tetrahedron.
std::vector<double> heights_over_boundary(const Mesh& mesh, const std::string& boundary);
/// The same, with each height's tetrahedron: (tetrahedron index, h_e) in mesh order.
std::vector<std::pair<Index, double>> tetrahedra_over_boundary(const Mesh& mesh,
                                                               const std::string& boundary);

/// The advice for every boundary with a pressure condition, before the first step: r_e =
/// c Δt / h_e² with Δt = time.dt (backward Euler), time.bdf.initial_step, or (BDF without it)
/// the bound kIdaFirstStepFraction × (first load-curve kink or t_end).
OscillationAdvice advise_oscillation(const Mesh& mesh, const Config& config);

/// The summary's `advisor` object: per face name h_min, h_median, h_max, r_min, r_median,
/// threshold, in_regime, elements, advice.
nlohmann::json to_json(const OscillationAdvice& advice);

/// Terminal lines: one per face, and a second with the remedies when in the regime.
std::vector<std::string> advice_lines(const OscillationAdvice& advice);

}  // namespace biphasic
