// Meshing a geometry with gmsh inside the gmsh module (defined in gmsh_mesh.cpp).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "../mesh/generator_support.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic::detail {

/// Element sizes of a gmsh-generated mesh: lc everywhere, or (graded) lc / grading_ratio on the
/// graded surfaces growing linearly to lc at distance grading_distance from them.
struct GmshSizing {
  double lc = 0.0;                ///< [mm]
  double grading_ratio = 1.0;     ///< ≥ 1; 1 = uniform
  double grading_distance = 0.0;  ///< [mm]
  double longest_side = 0.0;      ///< [mm] longest side of a graded surface (sets the sampling)
};

/// Meshes a geometry with gmsh inside a scoped session (see GmshSession in gmsh_mesh.cpp:
/// gmsh is left initialized or not, with its model and options, as found). `build` adds the
/// OCC geometry and its physical groups to the current model, synchronizes, and returns the
/// tags of the surfaces to grade toward (empty = uniform). The mesh is generated with
/// deterministic single-threaded options, raised to second order with edge nodes on the
/// geometry, written to `write_msh` (.msh 4.1) unless empty, and returned as a Mesh (corners
/// first, tets and boundary faces oriented). Throws on gmsh errors (as std::string) and
/// std::runtime_error otherwise; wrap in with_context.
Mesh mesh_with_gmsh(const GmshSizing& sizing, const std::string& write_msh,
                    const std::function<std::vector<int>()>& build);

/// Tags of the current model's surfaces, indexed like `names`: face_of(tag) gives the index
/// of each surface's face (names.size() or more for none). Throws std::runtime_error naming
/// `geometry` for a surface of no face or of a face already found, and naming a face that
/// has no surface.
std::vector<int> classify_surfaces(std::span<const char* const> names, const std::string& geometry,
                                   const std::function<std::size_t(int)>& face_of);

/// Adds one physical surface per tag, named names[i] with group tag i + 1 (so boundaries are
/// stored in this order), and the physical volume "domain" holding `volume`.
void add_physical_groups(int volume, std::span<const int> surfaces,
                         std::span<const char* const> names);

/// The quarter cylinder of an already validated spec (see generate_quarter_cylinder).
Mesh gmsh_quarter_cylinder(const QuarterCylinderSpec& spec);

/// The sphere octant of an already validated spec (see generate_sphere_octant).
Mesh gmsh_sphere_octant(const SphereOctantSpec& spec);

/// The mesh of a .msh file (see read_gmsh).
Mesh gmsh_read(const std::string& path);

/// Checks that `path` is a readable regular file, checks it with prescan_msh, merges it into a
/// fresh model of a scoped gmsh session and runs `body` on that model. Throws
/// std::runtime_error (or gmsh's std::string) without naming the file: wrap in with_context.
void with_msh_file(const std::string& path, const std::function<void()>& body);

/// The section mesh of a .msh file (see read_gmsh_section).
SectionMesh gmsh_read_section(const std::string& path);

}  // namespace biphasic::detail
