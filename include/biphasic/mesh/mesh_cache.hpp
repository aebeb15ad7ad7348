// On-disk cache of generated meshes. Generating the paper's quarter cylinder with gmsh takes
// 0.25 s on mesh 1 (2.5 s on mesh 4) and loading gmsh another 0.15–0.25 s; a cached mesh is
// read back, bit for bit the same, in milliseconds without loading gmsh at all.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/mesh_sources.hpp"

namespace biphasic {

/// Where generated meshes are cached: $BIPHASIC_MESH_CACHE if set ("off" or empty: no cache),
/// else $XDG_CACHE_HOME/biphasic/meshes, else $HOME/.cache/biphasic/meshes; an empty path when
/// caching is off or there is no home directory.
std::filesystem::path mesh_cache_directory();

/// Text that determines a generated mesh: every field of the spec that shapes it (numbers
/// exact, in hexadecimal floating point) and the identity of the mesher (gmsh module and
/// library files: a rebuilt module or an upgraded gmsh never reuses an older mesh).
/// `write_msh` is not part of it.
std::string mesh_description(const QuarterCylinderSpec& spec);
std::string mesh_description(const SphereOctantSpec& spec);

/// A mesh and whether it came from the cache.
struct CachedMesh {
  Mesh mesh;
  bool from_cache = false;
};

/// The mesh of `description`: read from `directory` if an earlier call stored it there (a file
/// named by a hash of the description, holding the description itself and a checksum), else
/// `generate()`d and stored (written to a temporary file and renamed, so that concurrent runs
/// never see a partial file). An empty `directory` disables the cache. A file that does not
/// match (other description, truncated, checksum wrong, older format) is regenerated and
/// replaced; so is an entry that decodes but is no valid mesh (an index out of range, counts
/// that disagree, a non-finite coordinate: check_mesh), with a note on stderr. Only regular
/// files of at most 2 GiB are read: a symbolic link, FIFO or device in place of an entry is a
/// miss (never followed, never blocks). Failing to store is not an error (the mesh is
/// returned all the same).
CachedMesh cached_mesh(const std::filesystem::path& directory, const std::string& description,
                       const std::function<Mesh()>& generate);

}  // namespace biphasic
