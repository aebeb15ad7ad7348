// Patch test: a homogeneous finite deformation with uniform pressure is reproduced exactly.
// Interior momentum rows vanish, boundary rows equal ∮ N_a P N dA, mass rows vanish.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <map>

#include "../common/box_mesh.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/boundary_integrals.hpp"

namespace biphasic {
namespace {

TEST(PatchTest, HomogeneousDeformationAndPressure) {
  const Mesh mesh = test::box_mesh({2, 2, 2}, {1.0, 1.5, 0.8});
  for (bool gls : {false, true}) {
    Config cfg;
    cfg.material = MaterialConfig::neo_hookean(0.2, 0.5, 1e-3);
    if (gls) cfg.stabilisation.type = "gls";
    BiphasicProblem problem(mesh, cfg);
    Mat3 F0;
    F0 << 0.95, 0.04, 0.02, -0.03, 1.02, 0.05, 0.01, -0.02, 0.97;
    const double p0 = 0.013;
    std::vector<double> y(problem.size(), 0.0), ydot(problem.size(), 0.0), R(problem.size());
    for (Index n = 0; n < mesh.num_nodes(); ++n) {
      const Vec3 X(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]);
      const Vec3 u = (F0 - Mat3::Identity()) * X;
      for (int c = 0; c < 3; ++c) y[3 * n + c] = u(c);
    }
    for (Index v = 0; v < mesh.num_vertices; ++v) y[problem.pattern().p_dof(v)] = p0;
    problem.residual(0.0, y.data(), ydot.data(), R.data());

    // Expected: ∮ N_a (P N) dA over the box surface, P = P_eff(F0) − p0 J F0⁻ᵀ.
    const NeoHookean m{0.2, 0.5};
    const Mat3 P = m.first_piola(F0) - p0 * F0.determinant() * F0.inverse().transpose();
    std::vector<double> expected(problem.num_u(), 0.0);
    const Vec3 centre(0.5, 0.75, 0.4);
    for (const Boundary& b : mesh.boundaries)
      for (const Tri6& f : b.faces) {
        Eigen::Matrix<double, 6, 3> X;
        for (int a = 0; a < 6; ++a)
          X.row(a) << mesh.nodes[f[a]][0], mesh.nodes[f[a]][1], mesh.nodes[f[a]][2];
        const Eigen::Matrix<double, 6, 3> NN =
            face_normal_integrals(X, centre - X.row(0).transpose());
        const Eigen::Matrix<double, 6, 3> t = NN * P.transpose();  // row a: ∫ N_a (P N)
        for (int a = 0; a < 6; ++a)
          for (int c = 0; c < 3; ++c) expected[3 * f[a] + c] += t(a, c);
      }
    double err = 0.0, scale = 0.0;
    for (Index i = 0; i < problem.num_u(); ++i) {
      err = std::max(err, std::abs(R[i] - expected[i]));
      scale = std::max(scale, std::abs(expected[i]));
    }
    EXPECT_LT(err, 1e-13 * std::max(scale, 1.0)) << (gls ? "with GLS" : "without GLS");
    EXPECT_GT(scale, 1e-4);
    for (Index i = problem.num_u(); i < problem.size(); ++i) EXPECT_NEAR(R[i], 0.0, 1e-15);
  }
}

TEST(PatchTest, UniformRateOfVolumeChange) {
  // ẏ from a homogeneous velocity gradient: R_p,c = J̇ ∫ N_c dV = J̇ Σ V_e/4 (straight tets).
  const Mesh mesh = test::box_mesh({2, 1, 1}, {1.0, 1.0, 1.0});
  Config cfg;
  BiphasicProblem problem(mesh, cfg);
  Mat3 Fdot;
  Fdot << 0.01, 0.002, 0.0, 0.0, -0.004, 0.001, 0.003, 0.0, 0.02;
  std::vector<double> y(problem.size(), 0.0), ydot(problem.size(), 0.0), R(problem.size());
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Vec3 v = Fdot * Vec3(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]);
    for (int c = 0; c < 3; ++c) ydot[3 * n + c] = v(c);
  }
  problem.residual(0.0, y.data(), ydot.data(), R.data());
  std::vector<double> volume_share(mesh.num_vertices, 0.0);
  for (const Tet10& t : mesh.tets) {
    const Vec3 x0(mesh.nodes[t[0]][0], mesh.nodes[t[0]][1], mesh.nodes[t[0]][2]);
    Vec3 e[3];
    for (int a = 1; a < 4; ++a)
      e[a - 1] = Vec3(mesh.nodes[t[a]][0], mesh.nodes[t[a]][1], mesh.nodes[t[a]][2]) - x0;
    const double V = e[0].cross(e[1]).dot(e[2]) / 6.0;
    for (int a = 0; a < 4; ++a) volume_share[t[a]] += V / 4.0;
  }
  for (Index v = 0; v < mesh.num_vertices; ++v)
    EXPECT_NEAR(R[problem.pattern().p_dof(v)], Fdot.trace() * volume_share[v], 1e-15);
}

}  // namespace
}  // namespace biphasic
