// The field output end to end (output.fields): a column stretched homogeneously in uniaxial
// strain under a uniform pore pressure writes the selected quantities and no others; the
// stress, J and flux in fields.h5 match the Neo-Hookean closed form in every element.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "../common/h5_reader.hpp"
#include "../common/run_binary.hpp"
#include "../common/uniaxial_column.hpp"
#include "biphasic/app/run.hpp"
#include "biphasic/io/case_file.hpp"

namespace biphasic {
namespace {

namespace fs = std::filesystem;
using test::H5Reader;

constexpr double kMu = 0.5, kLambda = 0.3, kPressure = 0.05;  // MPa
constexpr double kHeight = 2.0;                               // mm
constexpr double kStretch = 1.2;                              // λ_z at t = 1 s

std::string column_case(const std::string& fields) {
  std::ostringstream s;
  s << test::uniaxial_column_case({kMu, kLambda, kPressure, kStretch, 1.0, 1.5, kHeight});
  s << "[time]\nt_end = 1.0\ndt = 0.5\n"
    << "[linear_solver]\ntype = \"klu\"\nordering = \"amd\"\n"
    << "[output]\nline = false\nfields = " << fields << "\n";
  return s.str();
}

/// Runs the column case with `output.fields = fields` into a fresh folder; returns the folder.
fs::path run_column(const std::string& name, const std::string& fields) {
  const fs::path out =
      fs::temp_directory_path() / ("biphasic_fields_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(out);
  RunOptions options;
  options.output_dir = out.string();
  options.quiet = true;
  const nlohmann::json summary = run_case(parse_case(column_case(fields), "column.toml"), options);
  EXPECT_EQ(summary["status"], "completed");
  return out;
}

TEST(FieldOutput, SelectedFieldsAreWrittenAndMatchTheClosedForm) {
  const fs::path out = run_column("selected", R"(["flux", "J", "stress", "pressure"])");
  const H5Reader h5(out / "fields.h5");
  EXPECT_EQ(h5.read<double>("/fields/times", H5T_NATIVE_DOUBLE),
            (std::vector<double>{0.0, 0.5, 1.0}));
  for (const char* absent : {"displacement", "effective_stress", "permeability"})
    EXPECT_FALSE(h5.exists("/fields/" + std::string(absent))) << absent;
  EXPECT_TRUE(h5.exists("/fields/pressure/2"));
  EXPECT_TRUE(h5.exists("/fields/pressure_vertices/2"));

  const auto cells = static_cast<hsize_t>(h5.dims("/mesh/topology")[0]);
  EXPECT_EQ(h5.dims("/fields/stress/2"), (std::vector<hsize_t>{cells, 9}));
  EXPECT_EQ(h5.dims("/fields/J/2"), (std::vector<hsize_t>{cells}));
  EXPECT_EQ(h5.dims("/fields/flux/2"), (std::vector<hsize_t>{cells, 3}));
  EXPECT_EQ(h5.string_attribute("/fields/stress/2", "units"), "MPa");
  EXPECT_EQ(h5.string_attribute("/fields/flux/2", "units"), "mm/s");

  // F = diag(1, 1, s): σ = μ/J (b − I) + λ ln J / J I − p I, b = diag(1, 1, s²), J = s.
  const double s = kStretch, J = s;
  const double lateral = kLambda * std::log(J) / J - kPressure;
  const double axial = kMu / J * (s * s - 1.0) + lateral;
  const double expected[9] = {lateral, 0, 0, 0, lateral, 0, 0, 0, axial};  // row by row
  const auto stress = h5.read<double>("/fields/stress/2", H5T_NATIVE_DOUBLE);
  const auto volume_ratio = h5.read<double>("/fields/J/2", H5T_NATIVE_DOUBLE);
  const auto flux = h5.read<double>("/fields/flux/2", H5T_NATIVE_DOUBLE);
  for (hsize_t e = 0; e < cells; ++e) {
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(stress[9 * e + k], expected[k], 1e-10) << e << k;
    EXPECT_NEAR(volume_ratio[e], J, 1e-12) << e;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(flux[3 * e + c], 0.0, 1e-15) << e;
  }
  // At t = 0 nothing is stretched: σ = −p I.
  const auto stress0 = h5.read<double>("/fields/stress/0", H5T_NATIVE_DOUBLE);
  for (hsize_t e = 0; e < cells; ++e) EXPECT_NEAR(stress0[9 * e], -kPressure, 1e-12) << e;

  const std::string xdmf = e2e::read_text(out / "fields.xdmf");
  for (const char* attribute : {R"(Name="pressure" AttributeType="Scalar" Center="Node")",
                                R"(Name="stress" AttributeType="Tensor" Center="Cell")",
                                R"(Name="J" AttributeType="Scalar" Center="Cell")",
                                R"(Name="flux" AttributeType="Vector" Center="Cell")"})
    EXPECT_NE(xdmf.find(attribute), std::string::npos) << attribute;
  EXPECT_EQ(xdmf.find("displacement"), std::string::npos);
  EXPECT_EQ(xdmf.find("permeability"), std::string::npos);

  // The summary reports the selection in the canonical order.
  const auto summary = nlohmann::json::parse(e2e::read_text(out / "summary.json"));
  EXPECT_EQ(summary["configuration"]["output"]["fields"],
            nlohmann::json({"pressure", "stress", "J", "flux"}));
  fs::remove_all(out);
}

TEST(FieldOutput, TrueWritesDisplacementAndPressureOnly) {
  const fs::path out = run_column("default", "true");
  const H5Reader h5(out / "fields.h5");
  for (const char* present : {"displacement", "pressure", "pressure_vertices"})
    EXPECT_TRUE(h5.exists("/fields/" + std::string(present) + "/2")) << present;
  for (const char* absent : {"stress", "effective_stress", "J", "flux", "permeability"})
    EXPECT_FALSE(h5.exists("/fields/" + std::string(absent))) << absent;
  EXPECT_EQ(e2e::read_text(out / "fields.xdmf").find("Center=\"Cell\""), std::string::npos);
  const auto summary = nlohmann::json::parse(e2e::read_text(out / "summary.json"));
  EXPECT_EQ(summary["configuration"]["output"]["fields"], true);
  fs::remove_all(out);
}

TEST(FieldOutput, FalseAndEmptyListWriteNoFieldFiles) {
  for (const char* fields : {"false", "[]"}) {
    const fs::path out = run_column("none", fields);
    EXPECT_TRUE(fs::exists(out / "summary.json")) << fields;
    EXPECT_FALSE(fs::exists(out / "fields.h5")) << fields;
    EXPECT_FALSE(fs::exists(out / "fields.xdmf")) << fields;
    fs::remove_all(out);
  }
}

TEST(FieldOutput, UnknownNameIsRefusedNamingKeyValueAndChoices) {
  const fs::path dir = e2e::scratch_dir("biphasic_fields_bad");
  const fs::path case_file =
      e2e::write_text(dir / "bad.toml", column_case(R"(["stress", "strain"])"));
  const e2e::Result r = e2e::run("check " + case_file.string());
  EXPECT_EQ(r.status, 1) << r.output;
  for (const char* part :
       {"output.fields", "\"strain\" is not one of", "effective_stress", "permeability"})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << " in\n" << r.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace biphasic
