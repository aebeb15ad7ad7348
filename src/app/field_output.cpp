#include "biphasic/app/field_output.hpp"

#include <stdexcept>
#include <utility>

#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/field_recovery.hpp"
#include "biphasic/physics/section_field_recovery.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {

namespace {

bool is_nodal(FieldQuantity q) {
  return q == FieldQuantity::Displacement || q == FieldQuantity::Pressure;
}

/// Components and units of a cell quantity.
CellFieldSpec cell_spec(FieldQuantity q) {
  switch (q) {
    case FieldQuantity::Stress:
    case FieldQuantity::EffectiveStress:
      return {to_string(q), 9, "MPa"};
    case FieldQuantity::J:
      return {to_string(q), 1, "-"};
    case FieldQuantity::Flux:
      return {to_string(q), 3, "mm/s"};
    case FieldQuantity::Permeability:
      return {to_string(q), 1, "mm^4/(N s)"};
    case FieldQuantity::Displacement:
    case FieldQuantity::Pressure:
      break;
  }
  throw std::logic_error("field output: " + to_string(q) + " is not a cell field");
}

/// The recovered values of a cell quantity, moved out of `fields`.
std::vector<double> take(CellFields& fields, FieldQuantity q) {
  switch (q) {
    case FieldQuantity::Stress:
      return std::move(fields.stress);
    case FieldQuantity::EffectiveStress:
      return std::move(fields.effective_stress);
    case FieldQuantity::J:
      return std::move(fields.J);
    case FieldQuantity::Flux:
      return std::move(fields.flux);
    case FieldQuantity::Permeability:
      return std::move(fields.permeability);
    case FieldQuantity::Displacement:
    case FieldQuantity::Pressure:
      break;
  }
  throw std::logic_error("field output: " + to_string(q) + " is not a cell field");
}

std::vector<FieldQuantity> cell_quantities(const std::vector<FieldQuantity>& quantities) {
  std::vector<FieldQuantity> out;
  for (FieldQuantity q : quantities)
    if (!is_nodal(q)) out.push_back(q);
  return out;
}

}  // namespace

FieldLayout field_layout(const std::vector<FieldQuantity>& quantities) {
  FieldLayout layout;
  layout.displacement = false;
  layout.pressure = false;
  for (FieldQuantity q : quantities) {
    if (q == FieldQuantity::Displacement)
      layout.displacement = true;
    else if (q == FieldQuantity::Pressure)
      layout.pressure = true;
    else
      layout.cells.push_back(cell_spec(q));
  }
  return layout;
}

std::vector<std::vector<double>> selected_cell_values(const std::vector<FieldQuantity>& quantities,
                                                      CellFields& fields) {
  std::vector<std::vector<double>> cells;
  for (FieldQuantity q : cell_quantities(quantities)) cells.push_back(take(fields, q));
  return cells;
}

FieldOutput::FieldOutput(const std::vector<FieldQuantity>& quantities, const std::string& directory,
                         const Mesh& mesh, std::optional<double> keep_until)
    : cell_quantities_(cell_quantities(quantities)),
      writer_(keep_until
                  ? FieldWriter(directory, "fields", mesh, *keep_until, field_layout(quantities))
                  : FieldWriter(directory, "fields", mesh, field_layout(quantities))) {}

void FieldOutput::write(const BiphasicProblem& problem, double t, const std::vector<double>& y) {
  const auto num_u = static_cast<std::ptrdiff_t>(problem.num_u());
  const std::vector<double> u(y.begin(), y.begin() + num_u);
  const std::vector<double> p(y.begin() + num_u, y.end());
  std::vector<std::vector<double>> cells;
  if (!cell_quantities_.empty()) {
    CellFields fields = recover_cell_fields(problem, y.data());
    cells = selected_cell_values(cell_quantities_, fields);
  }
  writer_.write(t, u, p, cells);
}

SectionFieldOutput::SectionFieldOutput(const std::vector<FieldQuantity>& quantities,
                                       const std::string& directory, const SectionMesh& mesh,
                                       std::optional<double> keep_until)
    : cell_quantities_(cell_quantities(quantities)),
      writer_(keep_until
                  ? FieldWriter(directory, "fields", mesh, *keep_until, field_layout(quantities))
                  : FieldWriter(directory, "fields", mesh, field_layout(quantities))) {}

void SectionFieldOutput::write(const SectionProblem& problem, double t,
                               const std::vector<double>& y) {
  const auto num_u = static_cast<std::ptrdiff_t>(problem.num_u());
  const std::vector<double> u(y.begin(), y.begin() + num_u);  // 2 per node: the writer expands
  const std::vector<double> p(y.begin() + num_u, y.end());
  std::vector<std::vector<double>> cells;
  if (!cell_quantities_.empty()) {
    CellFields fields = recover_section_cell_fields(problem, y.data());
    for (FieldQuantity q : cell_quantities_) cells.push_back(take(fields, q));
  }
  writer_.write(t, u, p, cells);
}

}  // namespace biphasic
