// The field output of a run (fields.h5, fields.xdmf; docs/output_fields.md): the quantities
// output.fields selects, the nodal ones as solved, the element ones recovered from the state.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "biphasic/io/config.hpp"
#include "biphasic/io/field_writer.hpp"

namespace biphasic {

class BiphasicProblem;
class SectionProblem;
struct CellFields;

/// The writer's layout for `quantities`: displacement and pressure as nodal fields, the others
/// as cell fields named as in the case file, in FieldQuantity order.
FieldLayout field_layout(const std::vector<FieldQuantity>& quantities);

/// The cell quantities among `quantities`, each moved out of `fields` (element-major, as
/// CellFields), in the order of field_layout(quantities).cells.
std::vector<std::vector<double>> selected_cell_values(const std::vector<FieldQuantity>& quantities,
                                                      CellFields& fields);

/// Writes the selected quantities of each output state.
class FieldOutput {
 public:
  /// New files in `directory`, or with `keep_until` the files of the run being restarted,
  /// outputs after that time [s] dropped (FieldWriter). `quantities` must not be empty.
  FieldOutput(const std::vector<FieldQuantity>& quantities, const std::string& directory,
              const Mesh& mesh, std::optional<double> keep_until);

  /// Appends the state `y` (the problem's unknowns) at time `t` [s].
  void write(const BiphasicProblem& problem, double t, const std::vector<double>& y);

  const FieldWriter& writer() const { return writer_; }

 private:
  std::vector<FieldQuantity> cell_quantities_;  ///< in the layout's order
  FieldWriter writer_;
};

/// The field output of a two-dimensional model: the same files and quantities as FieldOutput
/// on the section mesh (Triangle_6 cells at z = 0, displacement with third component 0,
/// tensors' (2,2) entry σ_zz or the hoop σ_θθ; docs/output_fields.md).
class SectionFieldOutput {
 public:
  /// New files in `directory`, or with `keep_until` [s] those of the run being restarted.
  SectionFieldOutput(const std::vector<FieldQuantity>& quantities, const std::string& directory,
                     const SectionMesh& mesh, std::optional<double> keep_until);

  /// Appends the state `y` (u: 2 per node, then p per vertex) at time `t` [s].
  void write(const SectionProblem& problem, double t, const std::vector<double>& y);

  const FieldWriter& writer() const { return writer_; }

 private:
  std::vector<FieldQuantity> cell_quantities_;
  FieldWriter writer_;
};

}  // namespace biphasic
