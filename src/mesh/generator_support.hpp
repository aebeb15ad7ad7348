// Internal plumbing shared by the mesh generators and the gmsh module: spec checks, error
// context, face names.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
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

/// Face names of the generated quarter cylinder and sphere octant, in the order their
/// boundaries are stored (shared by the spec checks and the gmsh module that names the faces).
inline constexpr std::array<const char*, 5> kCylinderFaces{"bottom", "top", "lateral", "symmetry_x",
                                                           "symmetry_y"};
inline constexpr std::array<const char*, 4> kOctantFaces{"surface", "symmetry_x", "symmetry_y",
                                                         "symmetry_z"};

}  // namespace biphasic::detail
