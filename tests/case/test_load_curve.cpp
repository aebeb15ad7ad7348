// LoadCurve evaluation against hand-computed values.
#include <gtest/gtest.h>

#include <vector>

#include "biphasic/io/config.hpp"

namespace biphasic {
namespace {

// Rises 0 -> 1 over [0, 10] s, holds to 20 s, falls to -1 at 30 s; constant outside.
const LoadCurve kTrapezoid{{{0.0, 0.0}, {10.0, 1.0}, {20.0, 1.0}, {30.0, -1.0}}};

TEST(LoadCurve, Value) {
  EXPECT_DOUBLE_EQ(kTrapezoid.value(-5.0), 0.0);  // before the first point
  EXPECT_DOUBLE_EQ(kTrapezoid.value(0.0), 0.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.value(2.5), 0.25);
  EXPECT_DOUBLE_EQ(kTrapezoid.value(10.0), 1.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.value(15.0), 1.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.value(22.5), 0.5);
  EXPECT_DOUBLE_EQ(kTrapezoid.value(25.0), 0.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.value(30.0), -1.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.value(100.0), -1.0);  // after the last point
}

TEST(LoadCurve, SlopeIsTheRightDerivative) {
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(-5.0), 0.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(0.0), 0.1);  // at a point: the segment after it
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(5.0), 0.1);
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(10.0), 0.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(19.999), 0.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(20.0), -0.2);
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(29.0), -0.2);
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(30.0), 0.0);
  EXPECT_DOUBLE_EQ(kTrapezoid.slope(31.0), 0.0);
}

TEST(LoadCurve, KinksAreWhereTheSlopeJumps) {
  EXPECT_EQ(kTrapezoid.kinks(), (std::vector<double>{0.0, 10.0, 20.0, 30.0}));

  // The collinear point at 10 s and the flat end at 30 s are not kinks.
  const LoadCurve straight{{{0.0, 0.0}, {10.0, 1.0}, {20.0, 2.0}, {30.0, 2.0}}};
  EXPECT_EQ(straight.kinks(), (std::vector<double>{0.0, 20.0}));

  // A ramp's start and end are kinks (the curve is constant outside).
  const LoadCurve ramp{{{0.0, 0.0}, {32.0, 1.0}}};
  EXPECT_EQ(ramp.kinks(), (std::vector<double>{0.0, 32.0}));
}

TEST(LoadCurve, SinglePointIsConstant) {
  const LoadCurve constant{{{5.0, 0.7}}};
  EXPECT_DOUBLE_EQ(constant.value(-1.0), 0.7);
  EXPECT_DOUBLE_EQ(constant.value(5.0), 0.7);
  EXPECT_DOUBLE_EQ(constant.value(50.0), 0.7);
  EXPECT_DOUBLE_EQ(constant.slope(5.0), 0.0);
  EXPECT_TRUE(constant.kinks().empty());
}

TEST(LoadCurve, NoPointsIsZero) {
  const LoadCurve empty;
  EXPECT_DOUBLE_EQ(empty.value(3.0), 0.0);
  EXPECT_DOUBLE_EQ(empty.slope(3.0), 0.0);
  EXPECT_TRUE(empty.kinks().empty());
}

}  // namespace
}  // namespace biphasic
