// Probes end to end on an unstructured (gmsh) quarter cylinder: named [[probe]] lines off the
// mesh nodes, a probe line the nodes do not lie on, points outside the body refused by
// `check`, and output.line = false on a line that would not fit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_binary.hpp"

namespace {

namespace fs = std::filesystem;

using namespace biphasic::e2e;

fs::path folder() { return scratch_dir("biphasic_probes"); }

fs::path write_case(const std::string& name, const std::string& text) {
  return write_text(folder() / name, text);
}

// The paper's scene on a coarse unstructured mesh, two steps: the top pushed down 0.02 mm,
// top and bottom drained.
const std::string kScene = R"(format_version = 1
[mesh]
lc = 4.0
[curves]
ramp = [[0.0, 0.0], [12.8, 1.0]]
[[boundary]]
name = "top"
type = "displacement"
component = "z"
value = -0.02
curve = "ramp"
[[boundary]]
name = "bottom"
type = "displacement"
component = "z"
value = 0.0
[[boundary]]
name = "symmetry_x"
type = "symmetry"
[[boundary]]
name = "symmetry_y"
type = "symmetry"
[[boundary]]
name = "top"
type = "pressure"
value = 0.0
[[boundary]]
name = "bottom"
type = "pressure"
value = 0.0
[stabilisation]
type = "gls"
[time]
t_end = 12.8
dt = 6.4
)";

/// Rows of a probe CSV: t → rows of {s, x, y, z, ux, uy, uz, p}.
std::map<double, std::vector<std::array<double, 8>>> read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,s,x,y,z,ux,uy,uz,p") << path;
  std::map<double, std::vector<std::array<double, 8>>> rows;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    std::getline(ss, cell, ',');
    const double t = std::strtod(cell.c_str(), nullptr);
    std::array<double, 8> v{};
    for (double& x : v) {
      std::getline(ss, cell, ',');
      x = std::strtod(cell.c_str(), nullptr);
    }
    rows[t].push_back(v);
  }
  return rows;
}

nlohmann::json summary_of(const fs::path& dir) {
  return nlohmann::json::parse(read_text(dir / "summary.json"));
}

TEST(Probes, NamedProbesSampleAnUnstructuredMeshAnywhere) {
  const fs::path file = write_case("named.toml", kScene + R"([output]
fields = false
[[probe]]
name = "axis"
start = [0.0, 0.0, 0.0]
end = [0.0, 0.0, 8.0]
[[probe]]
name = "axis_fine"
start = [0.0, 0.0, 0.0]
end = [0.0, 0.0, 8.0]
points = 33
[[probe]]
name = "off_axis"
start = [5.0, 3.0, 0.0]
end = [5.0, 3.0, 8.0]
[[probe]]
name = "slant"
start = [0.7, 0.4, 0.3]
end = [11.0, 9.0, 7.6]
points = 25
)");
  const fs::path out = folder() / "named";
  const Result r = run("run " + file.string() + " -o " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;

  // Same segment, mesh nodes: the rows of line.csv.
  EXPECT_EQ(read_text(out / "probe_axis.csv"), read_text(out / "line.csv"));

  // The axis runs along element edges: between the nodes of an edge (vertex, edge node,
  // vertex) the P2 displacement is the quadratic through their values and the P1 pressure the
  // line through the two vertices' values.
  const auto nodes = read_csv(out / "line.csv");
  const auto fine = read_csv(out / "probe_axis_fine.csv");
  ASSERT_EQ(fine.size(), 3u);  // t = 0, 6.4, 12.8
  for (const auto& [t, rows] : fine) {
    const auto& n = nodes.at(t);
    ASSERT_EQ(n.size() % 2, 1u);
    ASSERT_EQ(rows.size(), 33u);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const double s = rows[i][0];
      EXPECT_NEAR(s, 8.0 * static_cast<double>(i) / 32.0, 1e-12);
      EXPECT_NEAR(rows[i][3], s, 1e-12);  // z = s on the axis
      std::size_t k = 0;                  // edge [n[k], n[k + 2]] containing s
      while (k + 2 < n.size() - 1 && s > n[k + 2][0]) k += 2;
      const double s0 = n[k][0], s1 = n[k + 1][0], s2 = n[k + 2][0];
      const double l0 = (s - s1) * (s - s2) / ((s0 - s1) * (s0 - s2));
      const double l1 = (s - s0) * (s - s2) / ((s1 - s0) * (s1 - s2));
      const double l2 = (s - s0) * (s - s1) / ((s2 - s0) * (s2 - s1));
      for (int c = 4; c < 7; ++c) {
        const double expected = l0 * n[k][c] + l1 * n[k + 1][c] + l2 * n[k + 2][c];
        EXPECT_NEAR(rows[i][c], expected, 1e-12) << "t " << t << " s " << s << " column " << c;
      }
      const double w = (s - s0) / (s2 - s0);
      EXPECT_NEAR(rows[i][7], (1 - w) * n[k][7] + w * n[k + 2][7], 1e-14)
          << "t " << t << " s " << s;
    }
  }

  // Off the nodes (a vertical line inside the body): 101 points by default. Its ends are on
  // the bottom (u_z = 0, p = 0) and the top (u_z = -0.02 t / 12.8, p = 0), whatever the mesh.
  const auto off = read_csv(out / "probe_off_axis.csv");
  for (const auto& [t, rows] : off) {
    ASSERT_EQ(rows.size(), 101u);
    EXPECT_NEAR(rows.front()[6], 0.0, 1e-14);
    EXPECT_NEAR(rows.back()[6], -0.02 * t / 12.8, 1e-14) << t;
    EXPECT_NEAR(rows.front()[7], 0.0, 1e-14);
    EXPECT_NEAR(rows.back()[7], 0.0, 1e-14);
    if (t > 0) {
      EXPECT_GT(rows[50][7], 1e-5) << "no pressure inside at t = " << t;
    }
  }
  const auto slant = read_csv(out / "probe_slant.csv");
  ASSERT_EQ(slant.at(12.8).size(), 25u);
  EXPECT_EQ(slant.at(12.8).back()[1], 11.0);
  EXPECT_EQ(slant.at(12.8).back()[3], 7.6);

  const nlohmann::json s = summary_of(out);
  EXPECT_EQ(s["line"]["sampling"], "mesh nodes");
  EXPECT_EQ(s["line"]["drained_ends"], "both");
  ASSERT_EQ(s["probes"].size(), 4u);
  EXPECT_EQ(s["probes"][0]["sampling"], "mesh nodes");
  EXPECT_EQ(s["probes"][1]["sampling"], "interpolated points");
  EXPECT_EQ(s["probes"][2]["points"], 101);
  EXPECT_EQ(s["probes"][3]["file"], "probe_slant.csv");
}

// A probe line the mesh nodes do not lie on was refused ("0 mesh vertices lie on the
// segment"); now it is sampled at 101 points and measured.
TEST(Probes, ProbeLineOffTheNodesIsInterpolatedAndMeasured) {
  const fs::path file = write_case("offline.toml", kScene + R"([output]
fields = false
line_start = [5.0, 3.0, 0.0]
line_end = [5.0, 3.0, 8.0]
)");
  const fs::path out = folder() / "offline";
  const Result r = run("run " + file.string() + " -o " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_csv(out / "line.csv").at(12.8).size(), 101u);
  const nlohmann::json s = summary_of(out);
  EXPECT_EQ(s["line"]["sampling"], "interpolated points");
  EXPECT_EQ(s["line"]["drained_ends"], "both");
  EXPECT_GT(s["outputs"].back()["p_mid"].get<double>(), 1e-5);
}

TEST(Probes, CheckRefusesPointsOutsideTheBody) {
  const fs::path file = write_case("outside.toml", kScene + R"([output]
line_start = [20.0, 20.0, 0.0]
line_end = [20.0, 20.0, 8.0]
[[probe]]
name = "beyond"
start = [1.0, 1.0, 4.0]
end = [30.0, 1.0, 4.0]
points = 2
)");
  for (const std::string command : {"check", "run"}) {
    const Result r = run(command + " " + file.string() + " -o " + (folder() / "outside").string());
    EXPECT_EQ(r.status, 1) << command << ":\n" << r.output;
    EXPECT_NE(r.output.find("outside.toml: probe[0] \"beyond\": point 2 of 2 at (30, 1, 4) mm "
                            "lies outside the body"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("outside.toml: output.line_start .. output.line_end: point 1 of 101 "
                            "at (20, 20, 0) mm lies outside the body (101 of the points do)"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("step "), std::string::npos) << "work started:\n" << r.output;
  }
  const fs::path inside = write_case("inside.toml", kScene);
  const Result ok = run("check " + inside.string());
  EXPECT_EQ(ok.status, 0) << ok.output;
}

// output.line = false: no probe line is built, so a line outside the body does not matter.
TEST(Probes, LineOffRunsWhereTheLineWouldNotFit) {
  const fs::path file = write_case("lineoff.toml", kScene + R"([output]
fields = false
line = false
line_start = [20.0, 20.0, 0.0]
line_end = [20.0, 20.0, 8.0]
)");
  EXPECT_EQ(run("check " + file.string()).status, 0);
  const fs::path out = folder() / "lineoff";
  const Result r = run("run " + file.string() + " -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "line.csv"));
  EXPECT_EQ(r.output.find("p_mid"), std::string::npos) << r.output;
  const nlohmann::json s = summary_of(out);
  EXPECT_EQ(s["line"]["enabled"], false);
  EXPECT_NE(s["line"]["note"].get<std::string>().find("output.line = false"), std::string::npos);
  for (const auto& o : s["outputs"]) EXPECT_FALSE(o.contains("p_mid")) << o;
  EXPECT_EQ(s["outputs"].size(), 3u);
}

}  // namespace
