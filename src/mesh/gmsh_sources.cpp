// The gmsh-made meshes: specs checked here, then handed to the gmsh module (loaded on first
// use, see gmsh_backend.hpp).
#include <stdexcept>
#include <string>

#include "biphasic/mesh/mesh_sources.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "generator_support.hpp"
#include "gmsh_backend.hpp"

namespace biphasic {

namespace {

void validate(const QuarterCylinderSpec& spec) {
  detail::require_positive("radius", spec.radius);
  detail::require_positive("height", spec.height);
  detail::require_positive("lc", spec.lc);
  detail::require_at_least_one("grading_ratio", spec.grading_ratio);
  if (!spec.grading_faces.empty()) {
    detail::require_positive("grading_distance", spec.grading_distance);
  }
  detail::require_known_faces(spec.grading_faces, detail::kCylinderFaces);
  if (spec.layers < 0) {
    throw std::runtime_error("layers = " + std::to_string(spec.layers) + " must be >= 0");
  }
  if (spec.layers > 0 && !spec.grading_faces.empty()) {
    throw std::runtime_error(
        "grading_faces (unstructured grading) and layers > 0 (a swept mesh) "
        "exclude each other; grade a swept mesh with layer_grading_faces");
  }
  if (spec.layers == 0 && !spec.layer_grading_faces.empty()) {
    throw std::runtime_error("layer_grading_faces needs layers > 0");
  }
}

void validate(const SphereOctantSpec& spec) {
  detail::require_positive("radius", spec.radius);
  detail::require_positive("lc", spec.lc);
  detail::require_at_least_one("grading_ratio", spec.grading_ratio);
  detail::require_positive("grading_distance", spec.grading_distance);
}

}  // namespace

Mesh generate_quarter_cylinder(const QuarterCylinderSpec& spec) {
  detail::with_context("generate_quarter_cylinder", [&] { validate(spec); });
  return detail::gmsh_backend().quarter_cylinder(spec);
}

Mesh generate_sphere_octant(const SphereOctantSpec& spec) {
  detail::with_context("generate_sphere_octant", [&] { validate(spec); });
  return detail::gmsh_backend().sphere_octant(spec);
}

Mesh read_gmsh(const std::string& path) { return detail::gmsh_backend().read(path); }

SectionMesh read_gmsh_section(const std::string& path) {
  return detail::gmsh_backend().read_section(path);
}

}  // namespace biphasic
