// Thread count from OMP_NUM_THREADS: used as given within a sane bound, clamped above it
// (OMP_NUM_THREADS=1000000 crashed the OpenMP runtime in assembly), ignored when not a
// positive integer.
#include <gtest/gtest.h>

#include "biphasic/assembly/threads.hpp"

namespace {

using biphasic::kMaxThreadsPerProcessor;
using biphasic::worker_threads_for;

TEST(WorkerThreads, PositiveCountsWithinTheBoundAreUsedAsGiven) {
  EXPECT_EQ(worker_threads_for("1", 2), 1);
  EXPECT_EQ(worker_threads_for("3", 2), 3);
  EXPECT_EQ(worker_threads_for("8", 2), 2 * kMaxThreadsPerProcessor);
}

TEST(WorkerThreads, HugeCountsAreClampedToThreadsPerProcessor) {
  EXPECT_EQ(worker_threads_for("1000000", 2), 2 * kMaxThreadsPerProcessor);
  EXPECT_EQ(worker_threads_for("99999999999999999999999", 2), 2);  // out of range: ignored
  EXPECT_EQ(worker_threads_for("2147483647", 16), 16 * kMaxThreadsPerProcessor);
}

TEST(WorkerThreads, UnsetOrInvalidValuesGiveTheProcessorCount) {
  EXPECT_EQ(worker_threads_for(nullptr, 6), 6);
  EXPECT_EQ(worker_threads_for("", 6), 6);
  EXPECT_EQ(worker_threads_for("abc", 6), 6);
  EXPECT_EQ(worker_threads_for("0", 6), 6);
  EXPECT_EQ(worker_threads_for("-4", 6), 6);
  EXPECT_EQ(worker_threads_for("4", 0), 4);  // no processor count known: at least one
}

}  // namespace
