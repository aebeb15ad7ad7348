// Manufactured solutions on the unit cube (N = 2, 4, 8): the exact loads are what they claim to
// be; the P1 pressure converges at order 2 in L² and the P2 displacement at order 3 where the
// pressure's own approximation error does not feed it (see docs/verification_mms.md).
#include <gtest/gtest.h>

#include "mms_study.hpp"

namespace biphasic::mms {
namespace {

TEST(ManufacturedSolution, FieldsAndLoadsAreConsistent) {
  for (bool linear : {false, true}) {
    Parameters m;
    m.linear_pressure = linear;
    const ManufacturedSolution exact(m);
    const Vec3 X(0.3, 0.7, 0.45);
    const double t = 0.8, h = 1e-5;
    // Hand-written gradients against central differences.
    const Spatial<double> f = spatial<double>(X, m);
    for (int J = 0; J < 3; ++J) {
      Vec3 Xp = X, Xm = X;
      Xp(J) += h;
      Xm(J) -= h;
      const Spatial<double> fp = spatial<double>(Xp, m), fm = spatial<double>(Xm, m);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(f.gradU(i, J), (fp.U(i) - fm.U(i)) / (2 * h), 1e-10) << i << J;
      EXPECT_NEAR(f.gradP(J), (fp.P - fm.P) / (2 * h), 1e-10) << J;
    }
    // Complex-step divergences against central differences of the real stress and flux.
    Vec3 divP = Vec3::Zero();
    double divQ = 0.0;
    for (int J = 0; J < 3; ++J) {
      Vec3 Xp = X, Xm = X;
      Xp(J) += h;
      Xm(J) -= h;
      divP +=
          (total_stress<double>(Xp, t, m).col(J) - total_stress<double>(Xm, t, m).col(J)) / (2 * h);
      divQ += (reference_flux<double>(Xp, t, m)(J) - reference_flux<double>(Xm, t, m)(J)) / (2 * h);
    }
    EXPECT_LT((exact.body_force(X, t) + divP).norm(), 1e-9);
    const double Jdot = (deformation_gradient<double>(f, t + h).determinant() -
                         deformation_gradient<double>(f, t - h).determinant()) /
                        (2 * h);
    EXPECT_NEAR(exact.fluid_source(X, t), Jdot - divQ, 1e-9);
    EXPECT_GT(std::abs(divQ), 1e-4);  // the Darcy term takes part
    // The state is finitely deformed, and at rest at t = 0 with no body force.
    EXPECT_GT(std::abs(deformation_gradient<double>(f, 1.0).determinant() - 1.0), 0.02);
    EXPECT_EQ(exact.body_force(X, 0.0).norm(), 0.0);
    EXPECT_GT(exact.body_force(X, t).norm(), 1e-3);
    EXPECT_GT(std::abs(exact.fluid_source(X, 0.0)), 1e-3);  // J̇(0) ≠ 0
  }
}

std::vector<MeshResult> study(const Parameters& m, const std::vector<int>& ns) {
  std::vector<MeshResult> runs;
  for (int n : ns) runs.push_back(solve_on_cube(n, StudyOptions{}, ManufacturedSolution(m)));
  return runs;
}

// The paper's permeability k = 1e-3: c t / L² ≈ 1e-3 at t = 1, the nearly undrained regime of
// the paper's loading.
TEST(ManufacturedSolution, ConvergesAtOrderThreeForDisplacementAndTwoForPressure) {
  Parameters m;
  m.k = 1e-3;
  const std::vector<MeshResult> runs = study(m, {2, 4, 8});
  report(runs, "convergence.csv");
  const std::vector<double> ru = observed_rates(runs, true), rp = observed_rates(runs, false);
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_GT(ru[i], 2.7) << "displacement, n = " << runs[i].n;
    EXPECT_GT(rp[i], 1.8) << "pressure, n = " << runs[i].n;
  }
}

// k = 0.1: the Darcy flux is comparable with J̇ (c t / L² ≈ 0.12). The pressure still converges
// at order 2. The displacement error now carries the elastic response to the pressure error,
// which for P1 is O(h²) in every norm (no gain in negative norms), so its observed rate falls
// from 3 toward 2 as h shrinks (measured 2.78, 2.53); the next test removes that part.
TEST(ManufacturedSolution, DrainedPressureConvergesAtOrderTwo) {
  Parameters m;
  m.k = 0.1;
  const std::vector<MeshResult> runs = study(m, {2, 4, 8});
  report(runs, "convergence_drained.csv");
  const std::vector<double> ru = observed_rates(runs, true), rp = observed_rates(runs, false);
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_GT(rp[i], 1.8) << "pressure, n = " << runs[i].n;
    EXPECT_GT(ru[i], 2.4) << "displacement, n = " << runs[i].n;
  }
}

// k = 0.1 with a pressure linear in X (exact in P1; the Darcy term still varies with J C⁻¹): the
// displacement converges at order 3.
TEST(ManufacturedSolution, DisplacementConvergesAtOrderThreeWhenP1HoldsThePressure) {
  Parameters m;
  m.k = 0.1;
  m.linear_pressure = true;
  const std::vector<MeshResult> runs = study(m, {2, 4, 8});
  report(runs, "convergence_linear_pressure.csv");
  const std::vector<double> ru = observed_rates(runs, true);
  for (std::size_t i = 1; i < runs.size(); ++i)
    EXPECT_GT(ru[i], 2.9) << "displacement, n = " << runs[i].n;
  EXPECT_LT(runs.back().errors.pressure, 1e-5 * runs.back().errors.pressure_norm);
}

}  // namespace
}  // namespace biphasic::mms
