// The assembled Jacobian dF/dy + c_j dF/dẏ in the fixed CSC pattern equals central differences
// of the assembled residual, Dirichlet rows included.
#include <gtest/gtest.h>

#include <random>

#include "../common/box_mesh.hpp"
#include "biphasic/physics/biphasic_problem.hpp"

namespace biphasic {
namespace {

Config column_config(bool gls) {
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(0.2, 0.5, 1e-2);
  if (gls) cfg.stabilisation.type = "gls";
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {1.0, 1.0}}};
  BoundaryCondition top{BcType::Displacement, "z1", 2, -0.05, {}, "ramp"};
  BoundaryCondition bottom{BcType::Displacement, "z0", 2, 0.0, {}, ""};
  BoundaryCondition sym{BcType::Symmetry, "x0", 0, 0.0, {}, ""};
  BoundaryCondition drained{BcType::Pressure, "z1", 0, 0.0, {}, ""};
  BoundaryCondition side{BcType::Traction, "x1", 0, 0.0, {0.01, 0.0, -0.02}, "ramp"};
  BoundaryCondition flux{BcType::Flux, "y1", 0, 1e-4, {}, ""};
  cfg.bcs = {top, bottom, sym, drained, side, flux};
  return cfg;
}

TEST(Assembly, JacobianMatchesDifferencesOfResidual) {
  const Mesh mesh = test::box_mesh({2, 1, 2}, {1.0, 1.0, 2.0});
  for (bool gls : {false, true}) {
    BiphasicProblem problem(mesh, column_config(gls));
    const Index n = problem.size();
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    std::vector<double> y(n), ydot(n);
    for (Index i = 0; i < n; ++i) {
      y[i] = (i < problem.num_u() ? 0.03 : 0.05) * d(gen);
      ydot[i] = 0.01 * d(gen);
    }
    const double t = 0.4, cj = 2.5;
    std::vector<double> values(problem.pattern().nnz());
    problem.jacobian(t, y.data(), ydot.data(), cj, values.data());
    const auto& cp = problem.pattern().colptr();
    const auto& ri = problem.pattern().rowind();
    double err = 0.0, scale = 0.0;
    std::vector<double> Fp(n), Fm(n);
    const double eps = 1e-6;
    for (Index j = 0; j < n; ++j) {
      std::vector<double> yp = y, ym = y, vp = ydot, vm = ydot;
      yp[j] += eps;
      ym[j] -= eps;
      vp[j] += cj * eps;
      vm[j] -= cj * eps;
      problem.residual(t, yp.data(), vp.data(), Fp.data());
      problem.residual(t, ym.data(), vm.data(), Fm.data());
      std::vector<double> col(n);
      for (Index i = 0; i < n; ++i) col[i] = (Fp[i] - Fm[i]) / (2 * eps);
      for (Index q = cp[j]; q < cp[j + 1]; ++q) {
        err = std::max(err, std::abs(col[ri[q]] - values[q]));
        scale = std::max(scale, std::abs(values[q]));
        col[ri[q]] = 0.0;
      }
      for (Index i = 0; i < n; ++i) EXPECT_EQ(col[i], 0.0) << "entry outside the pattern";
    }
    EXPECT_LT(err, 1e-7 * scale) << (gls ? "GLS" : "plain");
  }
}

}  // namespace
}  // namespace biphasic

namespace biphasic {
namespace {

// Consistent nodal loads of surface data: their sums are the resultant over the face.
TEST(Assembly, SurfaceLoadsSumToResultants) {
  const Mesh mesh = test::box_mesh({2, 3, 2}, {1.0, 1.5, 2.0});  // face x1 has area 3
  Config cfg;
  cfg.curves["half"] = LoadCurve{{{0.0, 0.5}}};
  cfg.bcs = {{BcType::Traction, "x1", 0, 0.0, {0.2, -0.1, 0.05}, ""},
             {BcType::NormalTraction, "y0", 0, 0.3, {}, "half"},  // area 2, outward N = −y
             {BcType::Flux, "z1", 0, 1e-3, {}, ""}};              // area 1.5
  BiphasicProblem problem(mesh, cfg);
  std::vector<double> y(problem.size(), 0.0), ydot(problem.size(), 0.0), R(problem.size());
  problem.residual(0.0, y.data(), ydot.data(), R.data());
  // At rest the body contributes nothing: R = −(traction loads) + flux loads.
  Vec3 force = Vec3::Zero();
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    for (int c = 0; c < 3; ++c) force(c) += R[3 * n + c];
  // −∫ t̄ dA over x1 − ∫ (−0.3 · 0.5 · N) dA over y0, with N = −e_y.
  const Vec3 expected = -3.0 * Vec3(0.2, -0.1, 0.05) + 0.15 * 2.0 * Vec3(0.0, -1.0, 0.0);
  EXPECT_LT((force - expected).norm(), 1e-13);
  double flux = 0.0;
  for (Index i = problem.num_u(); i < problem.size(); ++i) flux += R[i];
  EXPECT_NEAR(flux, 1e-3 * 1.5, 1e-16);
}

// Two material regions: each element runs its own region's laws. An element of the region with
// its own [[region]] entry gives exactly what a one-material problem of that material gives
// (residual, Jacobian, GLS coefficient); an element of the other region what [material] gives.
TEST(Assembly, RegionsUseTheirOwnLaws) {
  Mesh mesh = test::box_mesh({2, 1, 2}, {1.0, 1.0, 2.0});
  mesh.region_names = {"lower", "upper"};
  mesh.tet_region.resize(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    double z = 0.0;
    for (int c = 0; c < 4; ++c)
      z += 0.25 * mesh.nodes[static_cast<std::size_t>(mesh.tets[t][c])][2];
    mesh.tet_region[t] = z < 1.0 ? 0 : 1;
  }
  check_mesh(mesh);
  Config regions = column_config(true);
  RegionConfig upper{"upper", regions.material};
  upper.material.set("mu", 2.0);
  upper.material.set("permeability", 4e-2);
  regions.regions = {upper};
  Config only_upper = column_config(true);
  only_upper.material = upper.material;
  const Config only_material = column_config(true);

  BiphasicProblem problem(mesh, regions);
  BiphasicProblem reference_upper(mesh, only_upper);
  BiphasicProblem reference_lower(mesh, only_material);
  EXPECT_EQ(problem.oedometric_modulus(), 0.2 + 2.0 * 2.0);  // the largest H_A
  const Index n = problem.size();
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> y(n), ydot(n);
  for (Index i = 0; i < n; ++i) {
    y[i] = (i < problem.num_u() ? 0.03 : 0.05) * d(gen);
    ydot[i] = 0.01 * d(gen);
  }
  int counts[2] = {0, 0};
  for (Index e = 0; e < static_cast<Index>(mesh.tets.size()); ++e) {
    const int region = mesh.region_of(e);
    ++counts[region];
    BiphasicProblem& same = region == 1 ? reference_upper : reference_lower;
    BiphasicProblem& other = region == 1 ? reference_lower : reference_upper;
    EXPECT_EQ(problem.laws_of(e).p_wave_modulus(), same.laws_of(e).p_wave_modulus());
    EXPECT_EQ(problem.gls_coefficient(e), same.gls_coefficient(e));
    ElementOutput a, b, c;
    problem.element(e, y.data(), ydot.data(), true, a);
    same.element(e, y.data(), ydot.data(), true, b);
    other.element(e, y.data(), ydot.data(), true, c);
    EXPECT_EQ((a.residual - b.residual).norm(), 0.0) << "element " << e;
    EXPECT_EQ((a.dfdy - b.dfdy).norm(), 0.0) << "element " << e;
    EXPECT_GT((a.residual - c.residual).norm(), 1e-6 * a.residual.norm()) << "element " << e;
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);

  Config unknown = regions;
  unknown.regions[0].name = "bone";
  EXPECT_THROW(BiphasicProblem(mesh, unknown), std::runtime_error);
}

}  // namespace
}  // namespace biphasic
