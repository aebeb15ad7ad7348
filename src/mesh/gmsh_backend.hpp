// The gmsh mesher lives in a module of its own (libbiphasic_gmsh.so), loaded with dlopen on
// first use: gmsh and its ~90 shared libraries cost 0.15–0.25 s of dynamic linking at start-up,
// which a run on a cached mesh (mesh_cache.hpp) never needs to pay.
#pragma once

#include <string>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic::detail {

/// What the module provides (its symbol "biphasic_gmsh_backend" returns a pointer to one).
struct GmshBackend {
  /// Layout and meaning of this table; bumped whenever either changes.
  static constexpr int kAbi = 5;  // 5: read_section (SectionMesh) added
  int abi;
  Mesh (*quarter_cylinder)(const QuarterCylinderSpec&);  ///< spec already validated
  Mesh (*sphere_octant)(const SphereOctantSpec&);        ///< spec already validated
  Mesh (*read)(const std::string& path);
  SectionMesh (*read_section)(const std::string& path);
};

/// The module, loaded on the first call: from $BIPHASIC_GMSH_MODULE if set, else from where
/// the build put it. Throws std::runtime_error naming the path and the loader's message if it
/// cannot be loaded or does not match this build.
const GmshBackend& gmsh_backend();

/// Identity of the mesher for cache keys: module and gmsh library paths, sizes and
/// modification times (a rebuilt module or an upgraded gmsh gives another identity).
/// Does not load the module.
std::string gmsh_backend_identity();

}  // namespace biphasic::detail
