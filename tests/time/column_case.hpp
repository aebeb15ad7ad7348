// The confined column the time-integration tests share: 1 × 1 × 1 mm, 4 layers, its drained
// top pushed down over the first second and then held, sealed elsewhere.
#pragma once

#include <string>
#include <vector>

#include "biphasic/io/case_file.hpp"
#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic::column_case {

/// The case text: the top pushed down by `push` mm (e.g. "-0.05") along a ramp reaching it at
/// t = 1 s, dt = 1 s to t_end = 4 s (outputs at 1, 2, 3, 4 s), KLU with AMD, no field output;
/// `output` is appended to the [output] table.
inline std::string text(const std::string& push, const std::string& output = "") {
  return R"(
format_version = 1
[mesh]
source = "column"
[mesh.column]
width = 1.0
depth = 1.0
height = 1.0
nx = 1
ny = 1
nz = 4
[material]
lambda = 0.2
mu = 0.5
permeability = 1e-2
[curves]
ramp = [[0.0, 0.0], [1.0, 1.0]]
[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = )" +
         push +
         R"(
curve = "ramp"
[[boundary]]
name = "top"
type = "pressure"
value = 0.0
[[boundary]]
name = "bottom"
type = "displacement"
component = "z"
value = 0.0
[[boundary]]
name = "x0"
type = "symmetry"
[[boundary]]
name = "y0"
type = "symmetry"
[time]
t_end = 4.0
dt = 1.0
[linear_solver]
type = "klu"
ordering = "amd"
[output]
)" + output +
         "fields = false\n";
}

/// The case text parsed as file `name` with the --set `overrides`.
inline Config config(const std::string& push, const std::string& name,
                     const std::vector<std::string>& overrides = {},
                     const std::string& output = "") {
  return parse_case(text(push, output), name, overrides, ".");
}

/// The state at rest at time t0: zero but for the Dirichlet values of `problem` at t0.
inline std::vector<double> rest_state(const BiphasicProblem& problem, double t0 = 0.0) {
  std::vector<double> y(static_cast<std::size_t>(problem.size()), 0.0);
  problem.apply_dirichlet(t0, y.data(), nullptr);
  return y;
}

}  // namespace biphasic::column_case
