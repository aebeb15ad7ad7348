// The Holmes–Mow solid in drained, homogeneous compression of a column against the closed-form
// responses of include/biphasic/analytic/holmes_mow_uniaxial.hpp (docs/verification.md):
// uniaxial stress (lateral faces free, rollers on x0 and y0) and confined compression (rollers
// on all four sides), the top pushed down to 20 % strain in ten backward-Euler steps with p = 0
// at every pressure node. The deformation is homogeneous, which P2 elements represent exactly,
// so the platen stress (reaction on "top" over the area) equals the nominal stress P_zz up to
// the Newton tolerance. The reference is also checked against the 3D law at diagonal F.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "biphasic/analytic/holmes_mow_uniaxial.hpp"
#include "biphasic/material/holmes_mow_solid.hpp"
#include "verification_support.hpp"

namespace biphasic::verification {
namespace {

const analytic::HolmesMowParameters kParameters{0.8, 0.3, 0.6};  // E [MPa], ν, β
constexpr double kPush = -0.2;                                   // mm, 20 % of the height

/// One [[boundary]] entry of `type` on face `name`, with further `keys` lines.
std::string boundary(const std::string& name, const std::string& type,
                     const std::string& keys = "") {
  return "[[boundary]]\nname = \"" + name + "\"\ntype = \"" + type + "\"\n" + keys;
}

/// The column case: 1 × 1 × 1 mm, 1 × 1 × 2 cells (every pressure node on a face), drained
/// on every face, rollers on x0, y0 (and on x1, y1 if `confined`), the top pushed down by
/// 0.2 mm over t = 0…1 s in steps of 0.1 s with full Newton to a relative residual of 1e-12.
std::string column_text(bool confined) {
  std::string text = R"(
format_version = 1
[mesh]
source = "column"
[mesh.column]
width = 1.0
depth = 1.0
height = 1.0
nx = 1
ny = 1
nz = 2
[material]
solid_law = "holmes_mow"
youngs_modulus = 0.8
poissons_ratio = 0.3
beta = 0.6
permeability = 1e-3
[curves]
ramp = [[0.0, 0.0], [1.0, 1.0]]
[stabilisation]
type = "none"
[time]
integrator = "backward_euler"
t_end = 1.0
dt = 0.1
[time.newton]
rtol_displacement = 1e-12
max_setup_calls = 1
reuse_across_steps = false
[linear_solver]
type = "klu"
ordering = "amd"
[output]
line_start = [0.0, 0.0, 0.0]
line_end = [0.0, 0.0, 1.0]
fields = false
reactions = ["top", "bottom"]
)";
  text += boundary("top", "displacement", "component = \"z\"\nvalue = -0.2\ncurve = \"ramp\"\n");
  text += boundary("bottom", "displacement", "component = \"z\"\nvalue = 0.0\n");
  for (const char* face : {"x0", "y0"}) text += boundary(face, "symmetry");
  if (confined)
    for (const char* face : {"x1", "y1"}) text += boundary(face, "symmetry");
  for (const char* face : {"top", "bottom", "x0", "x1", "y0", "y1"})
    text += boundary(face, "pressure", "value = 0.0\n");
  return text;
}

struct ColumnResult {
  double max_error = 0.0;    ///< max |P_fe − P_zz| / |P_zz| over the outputs
  double max_balance = 0.0;  ///< max |F_top + F_bottom| / |F_top|
  int outputs = 0;
  double stress_at_20 = 0.0;  ///< P_zz at 20 % compression [MPa]
};

/// Runs the column and compares the platen stress with `reference(λ₁)` at every output.
template <class Reference>
ColumnResult run_column(bool confined, const std::string& label, Reference reference) {
  ScratchDir scratch("holmes_mow_" + label);
  const Config config = parse_case(column_text(confined), label + ".toml", {}, ".");
  RunOptions options;
  options.output_dir = (scratch.path() / label).string();
  options.quiet = true;
  const nlohmann::json summary = run_case(config, options);
  EXPECT_EQ(summary["status"], "completed") << label;
  const auto top = read_reactions(scratch.path() / label, "top");
  const auto bottom = read_reactions(scratch.path() / label, "bottom");
  const auto out = verification_output("holmes_mow_column");
  std::optional<CsvWriter> csv;
  if (out) csv.emplace(*out / (label + ".csv"), "t,stretch,stress_computed,stress_reference");
  ColumnResult r;
  for (const auto& [t, force] : top) {
    if (t <= 0.0) continue;
    const double stretch = 1.0 + kPush * t;  // height 1 mm, area 1 mm²
    const double expected = reference(stretch);
    r.max_error = std::max(r.max_error, std::abs(force[2] - expected) / std::abs(expected));
    r.max_balance =
        std::max(r.max_balance, std::abs(force[2] + bottom.at(t)[2]) / std::abs(force[2]));
    r.stress_at_20 = expected;
    ++r.outputs;
    if (csv) csv->row(t, stretch, force[2], expected);
  }
  return r;
}

// The reference at diagonal F against the 3D law: uniaxial lateral stress zero, P_zz equal.
TEST(HolmesMowColumn, ReferenceAgreesWithTheLaw) {
  const HolmesMowSolid law{kParameters.E, kParameters.nu, kParameters.beta};
  for (double stretch : {0.8, 0.9, 0.97, 1.0, 1.05, 1.2}) {
    const double lateral = analytic::holmes_mow_uniaxial_lateral_stretch(kParameters, stretch);
    const Mat3 P = law.first_piola(Mat3(Vec3(lateral, lateral, stretch).asDiagonal()));
    EXPECT_LT(std::abs(P(0, 0)), 1e-14) << stretch;
    EXPECT_NEAR(P(2, 2), analytic::holmes_mow_uniaxial_stress(kParameters, stretch), 1e-14);
    const Mat3 Pc = law.first_piola(Mat3(Vec3(1.0, 1.0, stretch).asDiagonal()));
    EXPECT_NEAR(Pc(2, 2), analytic::holmes_mow_confined_stress(kParameters, stretch), 1e-14);
  }
}

/// Runs the column and expects every output within 1e-10 of the reference (measured: about
/// 1e-14), top and bottom balanced to 1e-10.
template <class Reference>
void expect_column_matches(bool confined, const std::string& label, Reference reference) {
  const ColumnResult r = run_column(confined, label, reference);
  EXPECT_EQ(r.outputs, 10);
  EXPECT_LT(r.max_error, 1e-10);
  EXPECT_LT(r.max_balance, 1e-10);
  std::cout << "[ holmes_mow " << label << " ] max relative error " << r.max_error << ", balance "
            << r.max_balance << ", P_zz(0.8) = " << r.stress_at_20 << " MPa\n";
}

// Uniaxial stress to 20 % compression: platen stress = P_zz(λ₁, λ₂(λ₁)).
TEST(HolmesMowColumn, UniaxialStressMatchesTheClosedForm) {
  expect_column_matches(false, "uniaxial", [](double stretch) {
    return analytic::holmes_mow_uniaxial_stress(kParameters, stretch);
  });
}

// Confined compression to 20 %: platen stress = (H_A/2)(λ² − 1)/λ e^{β(λ²−1)} λ^{−2β}.
TEST(HolmesMowColumn, ConfinedCompressionMatchesTheClosedForm) {
  expect_column_matches(true, "confined", [](double stretch) {
    return analytic::holmes_mow_confined_stress(kParameters, stretch);
  });
}

}  // namespace
}  // namespace biphasic::verification
