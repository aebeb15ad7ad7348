// Size guard: an estimate of the unknowns and memory a case needs, made from the mesh
// parameters before any meshing, and a refusal (an input error) of cases that cannot fit in
// the memory the machine has.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "biphasic/io/config.hpp"

namespace biphasic {

/// What a case's mesh is expected to give.
struct SizeEstimate {
  double tets = 0.0;      ///< tetrahedra
  double unknowns = 0.0;  ///< 3 per P2 node (displacement) + 1 per vertex (pressure)
  double bytes = 0.0;     ///< peak memory of a run with the direct solver [bytes]
  std::string keys;       ///< the case keys the estimate comes from, e.g. "mesh.lc"
};

/// Tetrahedra and unknowns from the mesh parameters alone (no meshing):
///   column: exact, 6 nx ny nz tets, vertices and edges of the Kuhn lattice;
///   quarter cylinder / sphere octant (unstructured): volume / (0.18 h³) tets, h = lc, with
///     2 ∫ dV / (0.18 h³) over the graded band where h grows from lc / grading_ratio to lc;
///   swept quarter cylinder: (area / (0.43 lc²)) triangles × 3 × layers;
///   .msh file: the element count in its header (≈ 4.2 unknowns per tetrahedron).
/// A P2 tet mesh has ≈ 1.35 nodes and 1/6 vertex per tet, so unknowns ≈ 4.2 tets.
/// Memory: 0.1 GB + 4 GB × (unknowns / 243 000)^(4/3), calibrated on the paper's mesh 4
/// (243 k unknowns, about 4 GB with MUMPS); the 4/3 power is the fill of a sparse direct
/// factorisation in 3D.
SizeEstimate estimate_size(const Config& config);

/// MemAvailable from /proc/meminfo [bytes]; nullopt where it cannot be read.
std::optional<double> available_memory();

/// "about 1.2e+05 unknowns, 2.1 GB" for messages.
std::string describe(const SizeEstimate& estimate);

/// Throws CaseError ("<case>: <keys>: the mesh would have about N unknowns and need about
/// X GB, more than the Y GB available ...") when the estimate exceeds `available` bytes,
/// unless mesh.ignore_memory_estimate is set. Nothing happens when `available` is unknown.
void check_size(const Config& config, const std::string& case_path,
                std::optional<double> available);

}  // namespace biphasic
