// The progress meter: when a line is due, what it shows, and how the wall time left reads.
#include "biphasic/time/progress_meter.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace {

using biphasic::format_wall_time;
using biphasic::ProgressMeter;
using biphasic::ProgressSample;

TEST(ProgressMeter, WallTimeReadsInTheLargestFittingUnits) {
  EXPECT_EQ(format_wall_time(0.0), "< 1 s");
  EXPECT_EQ(format_wall_time(0.99), "< 1 s");
  EXPECT_EQ(format_wall_time(42.7), "42 s");
  EXPECT_EQ(format_wall_time(187.0), "3 min 07 s");
  EXPECT_EQ(format_wall_time(2 * 3600.0 + 5 * 60.0 + 30.0), "2 h 05 min");
  EXPECT_EQ(format_wall_time(1e12), "more than 30 years");
}

TEST(ProgressMeter, DueAfterItsInterval) {
  ProgressMeter every_step(0.0, 10.0, 0.0);
  EXPECT_TRUE(every_step.due());
  ProgressMeter rarely(0.0, 10.0, 1e9);
  EXPECT_FALSE(rarely.due());
  rarely.restart();
  EXPECT_FALSE(rarely.due());
}

TEST(ProgressMeter, TheLineShowsEveryField) {
  ProgressMeter meter(2.0, 12.0, 0.0);
  const std::string line = meter.line(ProgressSample{4.5, 0.25, 3, 17, 4, 2});
  for (const char* part : {"progress  t       4.5 s ( 25.0 %)", "h     0.25 s", "order 3",
                           "steps 17", "factorisations 4", "error-test failures 2", "wall left"})
    EXPECT_NE(line.find(part), std::string::npos) << "'" << part << "' not in " << line;
  // No simulated time done yet: nothing to extrapolate from.
  EXPECT_NE(meter.line(ProgressSample{2.0, 0.01, 1, 0, 0, 0}).find("wall left unknown"),
            std::string::npos);
}

TEST(ProgressMeter, IntervalFromTheEnvironment) {
  ::unsetenv("BIPHASIC_PROGRESS_INTERVAL");
  EXPECT_EQ(biphasic::progress_interval_from_environment(), biphasic::kDefaultProgressInterval);
  ::setenv("BIPHASIC_PROGRESS_INTERVAL", "0.5", 1);
  EXPECT_EQ(biphasic::progress_interval_from_environment(), 0.5);
  for (const char* bad : {"", "x", "-1", "1 s", "nan"}) {
    ::setenv("BIPHASIC_PROGRESS_INTERVAL", bad, 1);
    EXPECT_THROW(biphasic::progress_interval_from_environment(), std::invalid_argument) << bad;
  }
  ::unsetenv("BIPHASIC_PROGRESS_INTERVAL");
}

}  // namespace
