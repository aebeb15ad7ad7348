// How many threads the project's own OpenMP loops (assembly, the mixed-precision residual pass)
// may use.
#pragma once

namespace biphasic {

/// OMP_NUM_THREADS if set, else every processor. (gmsh sets the OpenMP default to its own
/// General.NumThreads while meshing, so the runtime's default cannot be trusted.)
int worker_threads();

}  // namespace biphasic
