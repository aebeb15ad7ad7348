// Oscillation measures on a pressure profile along a line (docs/formulation.md, "Measures").
//
// overshoot and undershoot compare the line's extremes with the pressure at mid-length p_mid.
// They suit the paper's scene, whose physical profile along the axis rises monotonically from
// the drained faces at both ends to a plateau in the middle. A physical maximum elsewhere is
// read as an overshoot: on a radius of Cryer's sphere (centre to drained surface) the
// Mandel–Cryer rise puts the maximum at the centre, and overshoot reports it (0.21 at T = 0.05).
//
// oscillation measures non-monotonicity instead, which is what a spurious pressure oscillation
// is: under a load that does not reverse, the physical pressure is monotone from a drained face
// to the point farthest from drainage. With p_i the pressure at the line's nodes in order,
//   TV = Σ |p_{i+1} − p_i|                          (total variation along the line)
//   V  = the least variation a profile with the same end values and at most m turning points
//        needs:  m = 0: V = |p_n − p_0|;  m = 1: V = max_k (|p_k − p_0| + |p_n − p_k|)
//   oscillation = (TV − V) / (2 |p_mid|)
// with m = 0 (monotone) when exactly one end of the line is drained, and m = 1 (one extremum
// anywhere: rising from each drained end to the middle, as in the paper's scene) when both
// are, or neither (where the physical extremum lies is then unknown). It is 0 exactly when the
// profile has at most m turning points, so Cryer's monotone profile gives 0 however high its
// centre value. Every reversal beyond those counts twice its height in TV − V: a single bump
// of height a above a monotone profile next to the drained face gives a / |p_mid|, the same
// as overshoot for the first step after a step load on Terzaghi's column, and an undershoot
// below the drained value counts like a bump. Reversals at round-off level count too (about
// 1e-12 on a flat profile); there is no tolerance inside the measure.
#pragma once

#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

class LineProbe;
class SemidiscreteSystem;

/// Which ends of a probe line lie on a drained boundary (a prescribed pressure).
enum class DrainedEnds { None, Start, End, Both };

/// "none", "start", "end" or "both".
std::string to_string(DrainedEnds ends);

/// Turning points a physical profile may have between the line's ends: 0 when exactly one end
/// is drained, 1 otherwise.
int allowed_turning_points(DrainedEnds ends);

struct LineMeasures {
  double p_mid = 0.0;        ///< pressure at mid-length of the line [MPa]
  double p_max = 0.0;        ///< [MPa]
  double p_min = 0.0;        ///< [MPa]
  double overshoot = 0.0;    ///< (max p − p_mid) / p_mid [-]
  double undershoot = 0.0;   ///< −min p / p_mid [-] (positive when p dips below zero)
  double oscillation = 0.0;  ///< (TV − V) / (2 |p_mid|) [-], see above
  bool defined = false;      ///< false when p_mid = 0 (ratios undefined)
};

/// Measures of the profile p(s) given at increasing arc lengths s [mm]; p_mid interpolated
/// linearly at the middle of [s.front(), s.back()]; `drained` selects the profile shape that
/// oscillation accepts. Throws std::invalid_argument for fewer than two points or unequal sizes.
LineMeasures line_measures(const std::vector<double>& s, const std::vector<double>& p,
                           DrainedEnds drained = DrainedEnds::None);

/// TV − V of the values p (in line order) for at most `turning_points` (0 or 1) turning points,
/// in the units of p; ≥ 0 up to round-off. Throws std::invalid_argument for other counts.
double excess_variation(const std::vector<double>& p, int turning_points);

/// The drained ends of `probe` in `problem` (a BiphasicProblem or a SectionProblem): an end is
/// drained when its pressure is interpolated from vertices whose pressure is prescribed
/// (Dirichlet pressure rows) only: a vertex with a prescribed pressure, an edge node between
/// two such vertices, or a point on a face (or edge, in a section) of them.
DrainedEnds drained_ends(const LineProbe& probe, const SemidiscreteSystem& problem);
/// The same from the Dirichlet flags of the unknowns (`constrained`, the pressure of vertex v at
/// first_pressure + v).
DrainedEnds drained_ends(const LineProbe& probe, const std::vector<char>& constrained,
                         Index first_pressure);

}  // namespace biphasic
