// Checks on a .msh file made before gmsh reads it: defects that gmsh 4.8 misreads or crashes on
// (inside the gmsh module; gmsh must be initialized).
#pragma once

#include <optional>
#include <string>

namespace biphasic::detail {

/// gmsh element type codes used by the reader.
inline constexpr int kGmshTri3 = 2;
inline constexpr int kGmshTet4 = 4;
inline constexpr int kGmshTri6 = 9;
inline constexpr int kGmshTet10 = 11;

/// What gmsh says of an element type.
struct GmshElementType {
  std::string name;   ///< e.g. "Tetrahedron 10"
  int num_nodes = 0;  ///< nodes per element
};

/// The name and node count of gmsh element type `type` (gmsh must be initialized); nullopt if
/// gmsh does not know the type.
std::optional<GmshElementType> gmsh_element_type(int type);

/// Reads the structure of a .msh file of format 2.x or 4.1 (ASCII or binary) without gmsh's
/// reader and throws std::runtime_error for the defects gmsh 4.8 does not survive:
/// - tetrahedra or triangles of both orders (gmsh keeps one element type per entity and
///   misreads, or overruns memory on, an entity mixing them);
/// - in format 2.x, an element naming a node that no $Nodes section before it defines (gmsh's
///   2.x reader reports it and then dereferences the missing node).
/// - a $PhysicalNames entry of a dimension other than 0-3 (gmsh's 4.x reader crashes on it;
///   checked in every format);
/// - in format 2.x, an element with partition tags (more than three tags): gmsh 4.8 crashes on
///   partition numbers it does not expect, and partitioned files are not read.
/// Files it does not understand (other formats, truncated sections, unknown element types) pass
/// unchanged: gmsh reports those itself.
void prescan_msh(const std::string& path);

}  // namespace biphasic::detail
