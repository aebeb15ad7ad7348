// Everything about a case that can be known before the first step, checked on its mesh by
// both `biphasic check` and `biphasic run` (docs/constraints.md).
#pragma once

#include <string>
#include <vector>

#include "biphasic/io/config.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/mesh/section_mesh.hpp"

namespace biphasic {

/// build_mesh (run.hpp), with the failures of a mesh file reported as bad input: a CaseError
/// "<case>: mesh.file = "<path>": <why>".
Mesh build_case_mesh(const Config& config, const std::string& output_dir,
                     bool* from_cache = nullptr);

/// Checks the case against its mesh and throws CaseError listing every problem (each naming
/// the case file, the key or boundary[i] and the value):
///  - every boundary[i].name is a boundary (physical surface) of the mesh, or for a
///    displacement condition a physical point or curve; mesh.grading_faces are boundaries;
///  - symmetry conditions lie on planes normal to x, y or z;
///  - no two conditions conflict: flux and pressure on one boundary; displacement (or
///    symmetry) conditions prescribing different values for the same component at shared
///    nodes; pressure conditions prescribing different values at shared vertices;
///  - the body force and fluid source formulas and their time rates are finite at every node
///    over [0, time.t_end];
///  - no two distinct nodes lie at the same place (unless constraints.allow_coincident_nodes);
///  - the displacement and symmetry conditions hold every rigid-body mode of every connected
///    part of the mesh (unless constraints.allow_free_rigid_modes).
/// Returns notes for the log (the opt-ins that were used and what they let through).
std::vector<std::string> preflight(const Config& config, const Mesh& mesh);

/// The section mesh of a two-dimensional model: generated ([mesh.section]) or read from
/// mesh.file, with failures reported as CaseError naming the key.
SectionMesh build_case_section_mesh(const Config& config);

/// The checks before the first step of a two-dimensional model, throwing CaseError listing
/// every problem: every boundary[i].name is a curve of the section mesh (or, for a
/// displacement condition, a physical point); the displacement and symmetry conditions hold
/// the rigid-body modes (plane strain: translations in x and y and the rotation about z;
/// axisymmetric: the translation along the axis, y) unless constraints.allow_free_rigid_modes;
/// the problem can be set up (conflicting conditions on one unknown, symmetry on a curve that is
/// not straight and axis-aligned, and the like, named by the condition).
std::vector<std::string> preflight_section(const Config& config, const SectionMesh& mesh);

/// `biphasic check`: builds the mesh as a run would (generated meshes through the mesh cache,
/// no .msh written), runs preflight on it and builds the probes. Returns preflight's notes,
/// then a line per probe (check_probes).
std::vector<std::string> check_case(const Config& config);

}  // namespace biphasic
