// Which rigid-body motions the displacement conditions leave free, part by part of the mesh.
//
// A body held only by conditions that a rigid motion u(X) = t + ω × (X − c) satisfies (e.g. a
// cylinder between frictionless platens: u_z fixed on top and bottom, nothing in x, y) has a
// singular stiffness: the solve drifts, or the direct solvers disagree. Before the first step
// the six rigid modes of every connected part (3 translations, 3 rotations about the part's
// centroid c) are restricted to the fixed displacement components; the modes in the null space
// of that restriction are free.
#pragma once

#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic {

/// A displacement component (0, 1, 2 = x, y, z) held at a node by some condition.
struct FixedComponent {
  Index node = 0;
  int component = 0;
};

/// Connected parts of the element graph (tetrahedra sharing a node belong to one part).
struct MeshParts {
  int count = 0;
  std::vector<int> part_of_node;  ///< per node: its part, −1 if used by no tetrahedron
  std::vector<Index> tets;        ///< per part: number of tetrahedra
};

/// The connected parts of `mesh`, numbered in order of their lowest tetrahedron index.
MeshParts connected_parts(const Mesh& mesh);

/// One free rigid motion, in words: "translation x", "rotation about z through (0, 0, 0.75)
/// mm" (the point of the axis nearest the part's centroid; left out when the translations
/// across the axis are free too, so that any parallel axis will do), "rotation about the axis
/// (0.6, 0.8, 0) through (…) mm", "translation along (…)".
struct FreeMode {
  std::string description;
  bool translation = false;  ///< a translation (else a rotation, possibly with a slide)
  int axis = -1;             ///< 0, 1, 2 when along / about a coordinate axis, else −1
};

/// The rigid motions one part of the mesh may make without violating the conditions.
struct PartFreedom {
  int part = 0;
  Index tets = 0;              ///< tetrahedra in the part
  Point centroid{};            ///< mean of the part's node positions [mm]
  double size = 0.0;           ///< largest distance of a node from the centroid [mm]
  Index fixed = 0;             ///< fixed components on the part's nodes
  std::vector<FreeMode> free;  ///< empty: every rigid mode is held
};

/// Per part of the mesh, the rigid modes left free by `fixed` (nodes outside the mesh are an
/// std::out_of_range). A mode counts as held when the smallest singular value of the
/// restriction (translations in mm, rotations scaled by the part's size) exceeds 1e-6, i.e. the
/// fixed components resist it with a lever of at least a millionth of the part's size.
std::vector<PartFreedom> free_rigid_modes(const Mesh& mesh,
                                          const std::vector<FixedComponent>& fixed);

}  // namespace biphasic
