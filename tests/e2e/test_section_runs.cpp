// Two-dimensional models through the command line: the paper's scene on the axisymmetric model
// (cases/paper/axisymmetric_k1e-3_nogls.toml) checks and runs, writes every output (summary with
// the model, the probe line on the axis, the platen reaction, Triangle_6 field files), keeps the
// fluid volume balance to the Newton tolerance with the conservative volume rate, continues
// from a checkpoint to the same answer, and refuses what a section cannot mean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_binary.hpp"

namespace biphasic {
namespace {

const std::string kCase =
    std::string(BIPHASIC_SOURCE_DIR) + "/cases/paper/axisymmetric_k1e-3_nogls.toml";

nlohmann::json summary_of(const std::filesystem::path& dir) {
  std::ifstream in(dir / "summary.json");
  return nlohmann::json::parse(in);
}

/// Rows of line.csv at time t: (s, p).
std::vector<std::pair<double, double>> line_at(const std::filesystem::path& dir, double t) {
  std::ifstream in(dir / "line.csv");
  std::string row;
  std::getline(in, row);
  std::vector<std::pair<double, double>> out;
  while (std::getline(in, row)) {
    std::vector<double> v;
    std::stringstream s(row);
    for (std::string cell; std::getline(s, cell, ',');) v.push_back(std::stod(cell));
    if (std::abs(v[0] - t) < 1e-9) out.emplace_back(v[1], v[8]);
  }
  return out;
}

TEST(SectionRuns, PaperSceneOnTheAxisymmetricModelWritesEveryOutput) {
  const e2e::FreshDir dir("section_run");
  const e2e::Result check = e2e::run("check " + kCase);
  ASSERT_EQ(check.status, 0) << check.output;
  const e2e::Result r = e2e::run("run " + kCase + " -o " + dir.dir.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  const nlohmann::json s = summary_of(dir.dir);
  EXPECT_EQ(s["status"], "completed");
  EXPECT_EQ(s["model"], "axisymmetric");
  EXPECT_EQ(s["mesh"]["triangles"], 2 * 32 * 14);
  EXPECT_EQ(s["mesh"]["unknowns"], 2 * 65 * 29 + 33 * 15);
  // The probe line is the axis: its 29 P2 nodes, both platens drained.
  EXPECT_EQ(s["line"]["nodes"], 29);
  EXPECT_EQ(s["line"]["drained_ends"], "both");
  const auto line = line_at(dir.dir, 32.0);
  ASSERT_EQ(line.size(), 29u);
  EXPECT_EQ(line.front().second, 0.0);  // drained platens
  EXPECT_EQ(line.back().second, 0.0);
  // At 1 % strain the mid-height pressure lies near the undrained limit μ(1/0.99 − 1) = 5.05e-3
  // MPa of the homogeneous isochoric state (the flow has barely begun at k = 1e-3).
  EXPECT_NEAR(line[14].second, 5.05e-3, 0.05 * 5.05e-3);
  // The platen force over the full circle: nearly the undrained one, 3μ ε π R² (the flow has
  // barely begun), slightly above it at 1 % finite strain.
  const double force = s["outputs"].back()["reactions"]["top"][1];
  const double undrained = -3.0 * 0.5 * 0.01 * 3.14159265358979 * 18.0 * 18.0;
  EXPECT_NEAR(force / undrained, 1.0, 0.01);
  // Field files on Triangle_6 cells.
  const std::string xdmf = e2e::read_text(dir.dir / "fields.xdmf");
  EXPECT_NE(xdmf.find("Triangle_6"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.dir / "fields.h5"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.dir / "reactions.csv"));
}

// With J̇ = (J − Jₙ)/Δt the discrete fluid volume balance holds to the Newton tolerance: the
// body's volume change equals the fluid that left through the platens.
TEST(SectionRuns, ConservativeVolumeRateKeepsTheFluidBalance) {
  const e2e::FreshDir dir("section_balance");
  const e2e::Result r = e2e::run("run " + kCase + " -o " + dir.dir.string() +
                                 " --quiet --set time.volume_rate=\"conservative\"");
  ASSERT_EQ(r.status, 0) << r.output;
  const nlohmann::json vb = summary_of(dir.dir)["outputs"].back()["volume_balance"];
  EXPECT_LT(vb["volume_change"].get<double>(), 0.0);  // compressed, fluid expelled
  EXPECT_LT(vb["relative_imbalance"].get<double>(), 1e-8) << vb.dump();
}

TEST(SectionRuns, RestartContinuesToTheSameAnswer) {
  const e2e::FreshDir straight("section_straight"), resumed("section_resumed");
  ASSERT_EQ(e2e::run("run " + kCase + " -o " + straight.dir.string() + " --quiet").status, 0);
  ASSERT_EQ(
      e2e::run("run " + kCase + " -o " + resumed.dir.string() + " --quiet --set time.t_end=19.2")
          .status,
      0);
  const e2e::Result r = e2e::run("run " + kCase + " --restart " + resumed.dir.string() +
                                 " --quiet --set time.t_end=32");
  ASSERT_EQ(r.status, 0) << r.output;
  // The same to the Newton tolerance (the restart factorises afresh where the whole run reuses
  // its factors, so the iterates differ below rtol = 1e-8).
  const auto a = line_at(straight.dir, 32.0), b = line_at(resumed.dir, 32.0);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(a[i].second - b[i].second));
    scale = std::max(scale, std::abs(a[i].second));
  }
  std::cout << "restart: largest difference " << worst / scale << " of max p\n";
  EXPECT_LT(worst, 1e-8 * scale);
}

TEST(SectionRuns, ConditionsAndPointsASectionCannotMeanAreRefusedBeforeWork) {
  // A curve the section does not have.
  e2e::Result r = e2e::run("check " + kCase + " --set boundary[2].name=\"lid\"");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("lid"), std::string::npos) << r.output;
  // A probe line off the plane.
  r = e2e::run("check " + kCase + " --set output.line_end=[0.0,8.0,1.0]");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("output.line_end"), std::string::npos) << r.output;
  // Nothing holds the translation in x of a plane-strain block standing on a frictionless
  // floor (the floor's y holds the rotation).
  const e2e::FreshDir dir("section_refused");
  const auto block = e2e::write_text(dir.dir / "block.toml", R"(format_version = 1
model = "plane_strain"
[mesh]
source = "section"
[mesh.section]
width = 1.0
height = 1.0
nr = 2
nz = 2
[[boundary]]
name = "bottom"
type = "displacement"
component = "y"
value = 0.0
[[boundary]]
name = "top"
type = "pressure"
value = 0.0
[output]
line_start = [0.5, 0.0, 0.0]
line_end = [0.5, 1.0, 0.0]
)");
  r = e2e::run("check " + block.string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("rigid-body modes free: the translation in x"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("rotation"), std::string::npos) << r.output;
  r = e2e::run("check " + block.string() + " --set constraints.allow_free_rigid_modes=true");
  EXPECT_EQ(r.status, 0) << r.output;
}

}  // namespace
}  // namespace biphasic
