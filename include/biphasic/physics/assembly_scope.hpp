// Which elements and rows a problem assembles when its mesh is one part's view of a larger mesh
// (mesh/partition.hpp), and the facts of the whole mesh its scales depend on (docs/parallel.md).
//
// Summing every part's residual gives the residual of the whole mesh when each part adds:
// - the integrals of its own elements only (volume terms, body force, fluid source);
// - face loads (traction, flux) only on the rows of the nodes it owns, whose faces it has in
//   full;
// - the rows of Dirichlet conditions only for the unknowns it owns.
// Its scales (Dirichlet row scales, tolerances, solution scales) come from the whole mesh, so
// that every part writes the same rows the same way. Rigid platens are posed on the summed
// system by the caller (parallel/distributed_platens.hpp): a part treats their unknowns as
// ordinary momentum unknowns.
#pragma once

#include <vector>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/partition.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/section_geometry.hpp"

namespace biphasic {

class RigidPlatens;

struct AssemblyScope {
  std::vector<char> element_owned;   ///< per element: its integrals are assembled here
  std::vector<char> node_owned;      ///< per node: its face loads are added here
  double mean_element_length = 0.0;  ///< tetrahedra: mean volume diameter over the whole mesh [mm]
  double section_depth = 0.0;        ///< triangles: section_mean_depth of the whole mesh [mm]
  Point lower{}, upper{};            ///< bounding box of the whole mesh [mm] (z = 0: triangles)
  std::vector<char> region_used;     ///< per region name: some element of the whole mesh has it
  /// The rigid platens of the whole mesh when the caller poses them on the summed system
  /// (needed only during construction). The part then neither ties nor sums their rows; it takes
  /// from them the solution scales, and each platen's unknowns on the part as the reaction rows
  /// of its boundary. Null: no platens, or (whole mesh) the problem poses its own.
  const RigidPlatens* platens = nullptr;
  /// The default scope: the whole mesh, assembled in one process.
  bool whole_mesh() const { return element_owned.empty(); }
};

/// The scope of part `sub` of `whole` (the mesh `sub.mesh` was extracted from).
AssemblyScope subdomain_scope(const Mesh& whole, const Subdomain& sub);
/// The same for a part of a two-dimensional model's section.
AssemblyScope subdomain_scope(const SectionMesh& whole, const SectionSubdomain& sub,
                              SectionModel model);

/// Mean volume diameter (6V/π)^(1/3) of the tetrahedra of `mesh` [mm] (0 without any).
double mean_element_length(const Mesh& mesh);

/// Bounding box of the nodes of `mesh` [mm] (z = 0 for a section).
std::pair<Point, Point> bounding_box(const Mesh& mesh);
std::pair<Point, Point> bounding_box(const SectionMesh& mesh);

}  // namespace biphasic
