// How many threads the project's own OpenMP loops (assembly, the mixed-precision residual pass)
// may use.
#pragma once

namespace biphasic {

/// More threads than this per processor only slow a run down; a larger OMP_NUM_THREADS (say
/// 1000000, which made the OpenMP runtime fail creating them) is clamped to it.
inline constexpr int kMaxThreadsPerProcessor = 4;

/// OMP_NUM_THREADS if set, else every processor; at most kMaxThreadsPerProcessor × the
/// processors (with a note on stderr when clamped). Also makes it the OpenMP default. (gmsh
/// sets the OpenMP default to its own General.NumThreads while meshing, so the runtime's
/// default cannot be trusted.)
int worker_threads();

/// The thread count for an OMP_NUM_THREADS value (nullptr: unset) on `processors`
/// processors: a positive integer is used up to kMaxThreadsPerProcessor × processors (one
/// beyond the range of long is clamped there too); anything else (empty, not a number, ≤ 0)
/// gives `processors`.
int worker_threads_for(const char* omp_num_threads, int processors);

}  // namespace biphasic
