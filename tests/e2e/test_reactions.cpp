// Reaction forces (output.reactions): a column stretched homogeneously in uniaxial strain under
// a uniform pore pressure, run end to end; every support force against the Neo-Hookean closed
// form, nominal stress × reference area, equal and opposite on opposite faces.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "../common/uniaxial_column.hpp"
#include "biphasic/analytic/confined_compression.hpp"
#include "biphasic/app/run.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;

constexpr double kMu = 0.5, kLambda = 0.3, kPressure = 0.05;  // MPa
constexpr double kWidth = 1.0, kDepth = 1.5, kHeight = 2.0;   // mm
constexpr double kStretch = 1.2;                              // λ_z at t = 1 s

std::string column_case() {
  std::ostringstream s;
  s << test::uniaxial_column_case({kMu, kLambda, kPressure, kStretch, kWidth, kDepth, kHeight});
  s << "[time]\nt_end = 1.0\ndt = 1.0\n"
    << "[linear_solver]\ntype = \"klu\"\nordering = \"amd\"\n"
    << "[output]\nline_start = [0, 0, 0]\nline_end = [0, 0, " << kHeight << "]\nfields = false\n"
    << "reactions = [\"top\", \"bottom\", \"x0\", \"x1\", \"y0\", \"y1\"]\n";
  return s.str();
}

/// Nominal total stress of F = diag(1, 1, s) under pore pressure p: P = P_eff − p J F⁻ᵀ,
/// P_eff = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ, J = s.
double axial_stress(double s, double p) {
  return analytic::neo_hookean_uniaxial_stress(kMu, kLambda, s) - p;
}
double lateral_stress(double s, double p) { return kLambda * std::log(s) - p * s; }

/// Expected reaction on each face: P N times the reference area (N the outward normal).
std::map<std::string, std::array<double, 3>> expected_reactions(double s, double p) {
  const double z = axial_stress(s, p) * kWidth * kDepth;
  const double x = lateral_stress(s, p) * kDepth * kHeight;
  const double y = lateral_stress(s, p) * kWidth * kHeight;
  return {{"top", {0, 0, z}}, {"bottom", {0, 0, -z}}, {"x0", {-x, 0, 0}},
          {"x1", {x, 0, 0}},  {"y0", {0, -y, 0}},     {"y1", {0, y, 0}}};
}

TEST(Reactions, HomogeneousUniaxialStrainMatchesTheClosedForm) {
  const fs::path out =
      fs::temp_directory_path() / ("biphasic_reactions_" + std::to_string(::getpid()));
  fs::remove_all(out);
  RunOptions options;
  options.output_dir = out.string();
  options.quiet = true;
  const nlohmann::json summary = run_case(parse_case(column_case(), "column.toml"), options);
  ASSERT_EQ(summary["status"], "completed");

  // reactions.csv: a row per boundary at t = 0 (pressure only, F = I) and t = 1 s (stretched).
  std::ifstream csv(out / "reactions.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "t,boundary,Fx,Fy,Fz");
  int rows = 0;
  while (std::getline(csv, line)) {
    std::stringstream cells(line);
    std::string t, name, f[3];
    std::getline(cells, t, ',');
    std::getline(cells, name, ',');
    for (auto& c : f) std::getline(cells, c, ',');
    const double s = std::stod(t) == 0.0 ? 1.0 : kStretch;
    // The six supports balance: their total (listed after them) vanishes.
    const auto expected = name == "total" ? std::array<double, 3>{0.0, 0.0, 0.0}
                                          : expected_reactions(s, kPressure).at(name);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(std::stod(f[c]), expected[c], 1e-9) << "t = " << t << ", " << name << ", " << c;
    ++rows;
  }
  EXPECT_EQ(rows, 14);

  // The same forces in the summary's outputs.
  const auto& last = summary["outputs"].back()["reactions"];
  const auto expected = expected_reactions(kStretch, kPressure);
  ASSERT_EQ(last.size(), 7u);
  for (const auto& [name, force] : expected)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(last[name][c].get<double>(), force[c], 1e-9) << name << ", " << c;
  EXPECT_GT(expected.at("top")[2], 0.0);  // the top support pulls the stretched column up
  fs::remove_all(out);
}

// A column under its own weight b (N/mm³), clamped at the bottom and held in z on the side
// x0 as well: the bottom edge on x0 is held in z by both. The total support force must balance
// the weight, −∫ b dV = −b w d h (global equilibrium of the free body), counting that edge once.
TEST(Reactions, TotalCountsRowsSharedByTwoBoundariesOnce) {
  constexpr double kWeight = -0.02;  // N/mm³, in z
  std::ostringstream s;
  s << "format_version = 1\n"
    << "[mesh]\nsource = \"column\"\n"
    << "[mesh.column]\nwidth = " << kWidth << "\ndepth = " << kDepth << "\nheight = " << kHeight
    << "\nnx = 2\nny = 2\nnz = 3\n"
    << "[material]\nmu = " << kMu << "\nlambda = " << kLambda << "\npermeability = 1e-3\n"
    << "[body_force]\nz = " << kWeight << "\n";
  for (const char* c : {"x", "y", "z"})
    s << "[[boundary]]\nname = \"bottom\"\ntype = \"displacement\"\ncomponent = \"" << c
      << "\"\nvalue = 0\n";
  s << "[[boundary]]\nname = \"x0\"\ntype = \"displacement\"\ncomponent = \"z\"\nvalue = 0\n"
    << "[[boundary]]\nname = \"top\"\ntype = \"pressure\"\nvalue = 0\n"
    << "[time]\nt_end = 1.0\ndt = 1.0\n"
    << "[time.newton]\nrtol_displacement = 1e-13\natol_displacement = 1e-15\n"
    << "[linear_solver]\ntype = \"klu\"\nordering = \"amd\"\n"
    << "[output]\nline_start = [0, 0, 0]\nline_end = [0, 0, " << kHeight << "]\nfields = false\n"
    << "reactions = [\"bottom\", \"x0\"]\n";
  const fs::path out =
      fs::temp_directory_path() / ("biphasic_reactions_total_" + std::to_string(::getpid()));
  fs::remove_all(out);
  RunOptions options;
  options.output_dir = out.string();
  options.quiet = true;
  const nlohmann::json summary = run_case(parse_case(s.str(), "weight.toml"), options);
  ASSERT_EQ(summary["status"], "completed");
  const auto& r = summary["outputs"].back()["reactions"];
  const double weight = kWeight * kWidth * kDepth * kHeight;  // N
  const double bottom = r["bottom"][2].get<double>(), side = r["x0"][2].get<double>();
  const double total = r["total"][2].get<double>();
  EXPECT_NEAR(total, -weight, 1e-9 * std::abs(weight));
  // Both boundaries carry part of the load, so adding them counts the shared edge twice.
  EXPECT_GT(std::abs(side), 1e-3 * std::abs(weight));
  EXPECT_GT(std::abs(bottom + side - total), 1e-3 * std::abs(weight));
  fs::remove_all(out);
}

TEST(Reactions, OnlyBoundariesWithDisplacementConditions) {
  const Config config = parse_case(column_case(), "column.toml");
  const Mesh mesh = build_mesh(config, "");
  BiphasicProblem problem(mesh, config);
  const std::vector<double> y(problem.size(), 0.0);
  EXPECT_THROW(problem.reactions({"nowhere"}, 0.0, y.data(), y.data()), std::invalid_argument);
  const auto r = problem.reactions({"top", "x1"}, 0.0, y.data(), y.data());
  ASSERT_EQ(r.size(), 3u);  // top, x1 and their total
  // At rest with p = 0 in y (the Dirichlet values not applied) every force vanishes.
  for (const auto& f : r)
    for (double c : f) EXPECT_EQ(c, 0.0);
}

}  // namespace
}  // namespace biphasic
