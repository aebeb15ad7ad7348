// Thread count from OMP_NUM_THREADS: used as given within a sane bound, clamped above it
// (OMP_NUM_THREADS=1000000 crashed the OpenMP runtime in assembly), ignored when not a
// positive integer.
#include <gtest/gtest.h>

#include <omp.h>

#include <cstdlib>
#include <string>

#include "biphasic/assembly/threads.hpp"

namespace {

using biphasic::kMaxThreadsPerProcessor;
using biphasic::worker_threads;
using biphasic::worker_threads_for;

TEST(WorkerThreads, PositiveCountsWithinTheBoundAreUsedAsGiven) {
  EXPECT_EQ(worker_threads_for("1", 2), 1);
  EXPECT_EQ(worker_threads_for("3", 2), 3);
  EXPECT_EQ(worker_threads_for("8", 2), 2 * kMaxThreadsPerProcessor);
}

TEST(WorkerThreads, HugeCountsAreClampedToThreadsPerProcessor) {
  EXPECT_EQ(worker_threads_for("1000000", 2), 2 * kMaxThreadsPerProcessor);
  // Beyond a long: as large as it gets, so clamped like any other large request.
  EXPECT_EQ(worker_threads_for("99999999999999999999999", 2), 2 * kMaxThreadsPerProcessor);
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

// worker_threads() reads OMP_NUM_THREADS itself: a huge value is clamped to
// kMaxThreadsPerProcessor per processor, with a note on stderr naming the value, and the clamped
// count becomes the OpenMP default. (No parallel region here: unclamped, it would start a million
// threads.)
TEST(WorkerThreads, AHugeEnvironmentValueIsClampedWithANoteAndBecomesTheDefault) {
  const char* before = std::getenv("OMP_NUM_THREADS");
  const std::string saved = before ? before : "";
  const int bound = kMaxThreadsPerProcessor * omp_get_num_procs();
  ASSERT_EQ(::setenv("OMP_NUM_THREADS", "1000000", 1), 0);
  ::testing::internal::CaptureStderr();
  const int threads = worker_threads();
  const std::string note = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(threads, bound);
  EXPECT_EQ(omp_get_max_threads(), bound);
  EXPECT_NE(note.find("OMP_NUM_THREADS=1000000 is more than " +
                      std::to_string(kMaxThreadsPerProcessor) + " threads per processor"),
            std::string::npos)
      << note;
  EXPECT_NE(note.find("using " + std::to_string(bound) + " threads"), std::string::npos) << note;

  // A count within the bound is used as given, silently.
  ASSERT_EQ(::setenv("OMP_NUM_THREADS", "1", 1), 0);
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(worker_threads(), 1);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(omp_get_max_threads(), 1);

  if (before)
    ::setenv("OMP_NUM_THREADS", saved.c_str(), 1);
  else
    ::unsetenv("OMP_NUM_THREADS");
  worker_threads();
}

}  // namespace
