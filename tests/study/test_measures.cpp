// Line measures (docs/formulation.md, "Measures") on synthetic profiles: overshoot and undershoot against p_mid,
// and the oscillation measure, which flags non-monotonicity and not a physical maximum.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "biphasic/study/measures.hpp"

namespace biphasic {
namespace {

/// s = 0, 1, ..., n − 1.
std::vector<double> arc(std::size_t n) {
  std::vector<double> s(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = static_cast<double>(i);
  return s;
}

TEST(LineMeasures, OvershootAndUndershootAgainstTheMidValue) {
  // Drained at both ends (the paper's axis): 0, −0.1, plateau 1 with a spike 1.3, −0.1, 0.
  const std::vector<double> p{0.0, -0.1, 1.3, 1.0, 1.0, 1.0, 1.3, -0.1, 0.0};
  const LineMeasures m = line_measures(arc(p.size()), p, DrainedEnds::Both);
  ASSERT_TRUE(m.defined);
  EXPECT_DOUBLE_EQ(m.p_mid, 1.0);
  EXPECT_DOUBLE_EQ(m.p_max, 1.3);
  EXPECT_DOUBLE_EQ(m.p_min, -0.1);
  EXPECT_NEAR(m.overshoot, 0.3, 1e-15);
  EXPECT_NEAR(m.undershoot, 0.1, 1e-15);
  // TV = 3.6 against 2.6 for the best one-extremum shape 0 → 1.3 → 0: the dips to −0.1 at
  // both faces and to 1.0 between the spikes, (0.1 + 0.3 + 0.1) / p_mid.
  EXPECT_NEAR(m.oscillation, 0.5, 1e-15);
}

TEST(LineMeasures, UndefinedWithoutAMidValue) {
  const LineMeasures m = line_measures({0.0, 1.0, 2.0}, {0.0, 0.0, 0.0}, DrainedEnds::End);
  EXPECT_FALSE(m.defined);
  EXPECT_EQ(m.overshoot, 0.0);
  EXPECT_EQ(m.oscillation, 0.0);
  EXPECT_THROW(line_measures({0.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(line_measures({0.0, 1.0}, {1.0}), std::invalid_argument);
}

// Cryer's sphere along a radius, centre to drained surface, during the Mandel–Cryer rise:
// p/P₀ from the series at T = 0.05 (r/R = 0, 0.1, ..., 1). The maximum is at the centre and
// overshoot reads 0.21; the profile is monotone, so oscillation is 0.
TEST(LineMeasures, OscillationIgnoresAMonotoneRiseAboveTheMidValue) {
  const std::vector<double> p{1.363718, 1.357579, 1.337347, 1.297722, 1.230590, 1.126611,
                              0.977962, 0.781800, 0.543178, 0.275849, 0.0};
  const LineMeasures m = line_measures(arc(p.size()), p, DrainedEnds::End);
  EXPECT_NEAR(m.overshoot, 0.2105, 1e-4);
  EXPECT_EQ(m.oscillation, 0.0);
  // Drained at the start instead (the line reversed): the same.
  const std::vector<double> reversed(p.rbegin(), p.rend());
  EXPECT_EQ(line_measures(arc(p.size()), reversed, DrainedEnds::Start).oscillation, 0.0);
}

// The first step after a step load q on a column, impermeable bottom (start) to drained top
// (end): undrained p = q, a spurious peak 1.6 q next to the drained face. oscillation equals
// overshoot, 0.6.
TEST(LineMeasures, OscillationFlagsASpuriousPeakNextToTheDrainedFace) {
  const std::vector<double> p{1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.6, 0.0};
  const LineMeasures m = line_measures(arc(p.size()), p, DrainedEnds::End);
  EXPECT_NEAR(m.overshoot, 0.6, 1e-12);
  EXPECT_NEAR(m.oscillation, 0.6, 1e-12);
  // With the decaying ripple the P2/P1 step leaves (a dip to 0.9 and a rise to 1.02 inside the
  // peak) every reversal counts.
  const std::vector<double> ripple{1.0, 1.0, 1.0, 1.0, 1.0, 1.02, 0.9, 1.6, 0.0};
  EXPECT_NEAR(line_measures(arc(ripple.size()), ripple, DrainedEnds::End).oscillation,
              0.02 + 0.1 + 0.6, 1e-12);
}

// A dip below the drained value (negative pressure next to the drained face) is a reversal.
TEST(LineMeasures, OscillationCountsAnUndershootBelowTheDrainedValue) {
  const std::vector<double> p{0.0, -0.2, 0.5, 1.0, 1.0, 1.0, 1.0};
  const LineMeasures m = line_measures(arc(p.size()), p, DrainedEnds::Start);
  EXPECT_NEAR(m.undershoot, 0.2, 1e-12);
  EXPECT_NEAR(m.oscillation, 0.2, 1e-12);
}

// Both ends drained (the paper's axis): the physical hump rising from each face to the middle
// is allowed; peaks next to both faces with a dip between are not. With one drained end the
// hump itself is a reversal.
TEST(LineMeasures, OneExtremumIsAllowedWhenBothEndsOrNeitherAreDrained) {
  const std::vector<double> hump{0.0, 0.5, 0.8, 0.95, 1.0, 0.95, 0.8, 0.5, 0.0};
  for (DrainedEnds ends : {DrainedEnds::Both, DrainedEnds::None})
    EXPECT_EQ(line_measures(arc(hump.size()), hump, ends).oscillation, 0.0) << to_string(ends);
  EXPECT_NEAR(line_measures(arc(hump.size()), hump, DrainedEnds::End).oscillation, 1.0, 1e-12);

  const std::vector<double> spurious{0.0, 1.2, 1.0, 1.0, 1.0, 1.0, 1.0, 1.2, 0.0};
  EXPECT_NEAR(line_measures(arc(spurious.size()), spurious, DrainedEnds::Both).oscillation, 0.2,
              1e-12);
}

TEST(LineMeasures, OscillationIsScaledByTheMidValueAndSignFree) {
  std::vector<double> p{1.0, 1.0, 1.0, 1.6, 0.0};
  const double base = line_measures(arc(p.size()), p, DrainedEnds::End).oscillation;
  for (double& x : p) x *= -3.0;  // suction instead of pressure, three times larger
  EXPECT_NEAR(line_measures(arc(p.size()), p, DrainedEnds::End).oscillation, base, 1e-12);
}

TEST(ExcessVariation, MonotoneAndUnimodalShapes) {
  EXPECT_EQ(excess_variation({}, 0), 0.0);
  EXPECT_EQ(excess_variation({2.0}, 1), 0.0);
  EXPECT_EQ(excess_variation({0.0, 1.0, 1.0, 3.0}, 0), 0.0);      // non-decreasing
  EXPECT_EQ(excess_variation({3.0, 1.0, 1.0, 0.0}, 0), 0.0);      // non-increasing
  EXPECT_NEAR(excess_variation({0.0, 2.0, 1.0}, 0), 2.0, 1e-15);  // one bump of height 1
  EXPECT_EQ(excess_variation({0.0, 2.0, 1.0}, 1), 0.0);
  EXPECT_EQ(excess_variation({1.0, 0.0, 2.0}, 1), 0.0);  // a valley is one turning point too
  EXPECT_NEAR(excess_variation({0.0, 2.0, 1.0, 3.0, 0.0}, 1), 2.0, 1e-15);
  EXPECT_THROW(excess_variation({0.0, 1.0}, 2), std::invalid_argument);
  EXPECT_THROW(excess_variation({0.0, 1.0}, -1), std::invalid_argument);
}

TEST(DrainedEnds, Names) {
  EXPECT_EQ(to_string(DrainedEnds::None), "none");
  EXPECT_EQ(to_string(DrainedEnds::Start), "start");
  EXPECT_EQ(to_string(DrainedEnds::End), "end");
  EXPECT_EQ(to_string(DrainedEnds::Both), "both");
  EXPECT_EQ(allowed_turning_points(DrainedEnds::Start), 0);
  EXPECT_EQ(allowed_turning_points(DrainedEnds::End), 0);
  EXPECT_EQ(allowed_turning_points(DrainedEnds::Both), 1);
  EXPECT_EQ(allowed_turning_points(DrainedEnds::None), 1);
}

}  // namespace
}  // namespace biphasic
