// Internal plumbing shared by the mesh generators: spec checks, error context, and meshing a
// gmsh geometry with the project's deterministic options (defined in gmsh_mesh.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/mesh/mesh.hpp"

namespace biphasic::detail {

/// Throws "<what> must be positive and finite, got <value>" unless 0 < value < ∞.
inline void require_positive(const char* what, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    std::ostringstream msg;
    msg << what << " must be positive and finite, got " << value;
    throw std::runtime_error(msg.str());
  }
}

/// Throws "<what> must be >= 1, got <value>" unless 1 ≤ value < ∞.
inline void require_at_least_one(const char* what, double value) {
  if (!(std::isfinite(value) && value >= 1.0)) {
    std::ostringstream msg;
    msg << what << " must be >= 1, got " << value;
    throw std::runtime_error(msg.str());
  }
}

/// Throws "unknown grading face '<name>' (valid names: a, b, …)" for the first name in `names`
/// that is not in `valid`.
inline void require_known_faces(const std::vector<std::string>& names,
                                std::span<const char* const> valid) {
  for (const std::string& name : names) {
    if (std::find(valid.begin(), valid.end(), name) != valid.end()) continue;
    std::string list;
    for (const char* face : valid) list += (list.empty() ? "" : ", ") + std::string(face);
    throw std::runtime_error("unknown grading face '" + name + "' (valid names: " + list + ")");
  }
}

/// Runs `body` and rethrows its failures as std::runtime_error prefixed by "<context>: "
/// (gmsh's std::string exceptions as "<context>: gmsh: <message>").
template <class Body>
auto with_context(const std::string& context, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const std::string& message) {
    throw std::runtime_error(context + ": gmsh: " + message);
  } catch (const std::exception& e) {
    throw std::runtime_error(context + ": " + e.what());
  }
}

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

}  // namespace biphasic::detail
