// The whole mesh from one process to all (docs/parallel.md): process `root` builds or reads it
// (through the mesh cache), the others receive a copy, so that no two processes generate or
// write the same cache entry.
#pragma once

#include <mpi.h>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// On `root`, sends `mesh`; elsewhere, replaces `mesh` with the root's. Collective over `comm`.
void broadcast_mesh(Mesh& mesh, MPI_Comm comm, int root = 0);
void broadcast_mesh(SectionMesh& mesh, MPI_Comm comm, int root = 0);

}  // namespace biphasic
