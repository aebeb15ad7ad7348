// The gmsh module's one exported symbol: the table of its meshing functions, which the core
// loads on first use (src/mesh/gmsh_backend.cpp) so that runs on a cached mesh never load gmsh.
#include "../mesh/gmsh_backend.hpp"
#include "gmsh_meshing.hpp"

extern "C" __attribute__((visibility("default"))) const biphasic::detail::GmshBackend*
biphasic_gmsh_backend() {
  static const biphasic::detail::GmshBackend backend{
      biphasic::detail::GmshBackend::kAbi, &biphasic::detail::gmsh_quarter_cylinder,
      &biphasic::detail::gmsh_sphere_octant, &biphasic::detail::gmsh_read,
      &biphasic::detail::gmsh_read_section};
  return &backend;
}
