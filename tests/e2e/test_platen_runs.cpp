// Rigid platens through the command line (cases/verification/confined_creep and mandel): the
// creep case runs with both integrators and writes platens.csv and the summary's platen record,
// its settlement follows Terzaghi's degree of consolidation, a restart appends to platens.csv
// and reaches the same answer, and what a platen cannot be is refused before any work.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_binary.hpp"

namespace biphasic {
namespace {

const std::string kCreep =
    std::string(BIPHASIC_SOURCE_DIR) + "/cases/verification/confined_creep/confined_creep.toml";
const std::string kMandel =
    std::string(BIPHASIC_SOURCE_DIR) + "/cases/verification/mandel/mandel.toml";
constexpr double kForce = -1.5079644737231007e-4;  // [N], the case's platen force
constexpr double kFinal = 1e-3;                    // q H / H_A [mm]
constexpr double kTEndHalf = 416.66666666666667;   // T = 0.5 [s]
constexpr double kUHalf = 0.7639504;               // Terzaghi's U(0.5)

struct PlatenRow {
  double t, displacement, force;
};

std::vector<PlatenRow> platen_rows(const std::filesystem::path& dir) {
  std::ifstream in(dir / "platens.csv");
  std::string row;
  std::getline(in, row);
  EXPECT_EQ(row, "t,platen,displacement,force");
  std::vector<PlatenRow> out;
  while (std::getline(in, row)) {
    std::vector<std::string> cells;
    std::stringstream s(row);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    EXPECT_EQ(cells.size(), 4u);
    EXPECT_EQ(cells[1], "top");
    out.push_back({std::stod(cells[0]), std::stod(cells[2]), std::stod(cells[3])});
  }
  return out;
}

nlohmann::json summary_of(const std::filesystem::path& dir) {
  std::ifstream in(dir / "summary.json");
  return nlohmann::json::parse(in);
}

TEST(PlatenRuns, CreepCaseSettlesAsTerzaghiWithBothIntegrators) {
  for (const std::string integrator : {"bdf", "backward_euler"}) {
    const e2e::FreshDir dir("platen_creep_" + integrator);
    const e2e::Result r =
        e2e::run("run " + kCreep + " -o " + dir.dir.string() + " --quiet --set time.t_end=" +
                 std::to_string(kTEndHalf) + " --set time.integrator=" + integrator +
                 (integrator == "bdf" ? "" : " --set time.dt=1.6666666666666667"));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::vector<PlatenRow> rows = platen_rows(dir.dir);
    ASSERT_GT(rows.size(), 10u);
    EXPECT_EQ(rows.front().t, 0.0);
    EXPECT_NEAR(rows.back().t, kTEndHalf, 1e-6);  // t_end given to 6 decimals
    for (const PlatenRow& row : rows) EXPECT_EQ(row.force, kForce);
    // Settlement (downward: negative displacement) against U(T = 0.5).
    EXPECT_NEAR(-rows.back().displacement / kFinal, kUHalf, 3e-3) << integrator;
    const nlohmann::json s = summary_of(dir.dir);
    ASSERT_EQ(s["platens"].size(), 1u);
    EXPECT_EQ(s["platens"][0]["boundary"], "top");
    EXPECT_EQ(s["platens"][0]["component"], 1);
    EXPECT_NEAR(s["platens"][0]["area"].get<double>(), M_PI * 0.2 * 0.2, 1e-12);
    const nlohmann::json& last = s["outputs"].back();
    EXPECT_EQ(last["platens"]["top"]["displacement"].get<double>(), rows.back().displacement);
    // The platen's reaction is its load; the bottom carries it.
    const double top = last["reactions"]["top"][1], bottom = last["reactions"]["bottom"][1];
    EXPECT_NEAR(top, kForce, 1e-8 * std::abs(kForce));
    EXPECT_NEAR(bottom, -kForce, 1e-6 * std::abs(kForce));
  }
}

TEST(PlatenRuns, RestartAppendsToPlatensCsvAndReachesTheSameSettlement) {
  const e2e::FreshDir straight("platen_straight"), resumed("platen_resumed");
  const std::string end = " --set time.t_end=" + std::to_string(kTEndHalf);
  ASSERT_EQ(e2e::run("run " + kCreep + " -o " + straight.dir.string() + " --quiet" + end).status,
            0);
  ASSERT_EQ(e2e::run("run " + kCreep + " -o " + resumed.dir.string() +
                     " --quiet --set time.t_end=208.33333333333334")
                .status,
            0);
  const e2e::Result r =
      e2e::run("run " + kCreep + " --restart " + resumed.dir.string() + " --quiet" + end);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<PlatenRow> a = platen_rows(straight.dir), b = platen_rows(resumed.dir);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i].t, b[i].t, 1e-9);
  // The same to the integrator's tolerance (IDA restarts at order 1; rtol = 1e-6).
  EXPECT_NEAR(a.back().displacement, b.back().displacement, 5e-5 * kFinal);
}

TEST(PlatenRuns, WhatAPlatenCannotBeIsRefusedBeforeWork) {
  ASSERT_EQ(e2e::run("check " + kMandel).status, 0);
  const e2e::Result iterative = e2e::run("check " + kCreep + " --set linear_solver.type=iterative");
  EXPECT_EQ(iterative.status, 1);
  EXPECT_NE(iterative.output.find("linear_solver.type"), std::string::npos) << iterative.output;
  EXPECT_NE(iterative.output.find("rigid_platen, which needs a direct solver"), std::string::npos)
      << iterative.output;
  // The chamber wall holding the platen's corner node along the platen's axis.
  const e2e::FreshDir dir("platen_held");
  const e2e::Result held =
      e2e::run("run " + kCreep + " -o " + dir.dir.string() +
               " --quiet --set boundary[3].type=displacement --set boundary[3].component=y"
               " --set boundary[3].value=0");
  EXPECT_EQ(held.status, 1);
  EXPECT_NE(held.output.find("boundary[0] (rigid_platen on 'top'): node"), std::string::npos)
      << held.output;
  EXPECT_NE(held.output.find("is also held along the platen's component"), std::string::npos)
      << held.output;
}

}  // namespace
}  // namespace biphasic
