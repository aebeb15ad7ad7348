// Rigid platens under a prescribed force (physics/rigid_platen.hpp), on both problems: the
// assembled Jacobian (dF/dy + c_j dF/dẏ and dF/dẏ alone) against central differences of the
// assembled residual, the force row against the reaction of the same state under a prescribed
// displacement (an independent path: the reaction sums the momentum rows of the Dirichlet
// problem), the ties, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../common/box_mesh.hpp"
#include "../common/every_condition.hpp"
#include "biphasic/mesh/section_mesh.hpp"
#include "biphasic/physics/biphasic_problem.hpp"
#include "biphasic/physics/section_problem.hpp"

namespace biphasic {
namespace {

constexpr double kForce = -0.02;  // [N]

SectionMesh small_section() {
  SectionRectangleSpec spec;
  spec.width = 1.0;
  spec.height = 0.6;
  spec.nr = 3;
  spec.nz = 2;
  return generate_section_rectangle(spec);
}

/// A compressed column: bottom held, `top` a rigid platen along the last axis (or a prescribed
/// displacement of that component when `platen` is false), a drained lateral side, GLS.
Config platen_config(bool three_d, bool platen, const std::string& stabilisation = "gls") {
  Config cfg;
  cfg.material = MaterialConfig::neo_hookean(0.3, 0.6, 1e-2);
  cfg.stabilisation.type = stabilisation;
  cfg.curves["ramp"] = LoadCurve{{{0.0, 0.0}, {2.0, 1.0}}};
  const int axial = three_d ? 2 : 1;
  const std::string top = three_d ? "z1" : "top", bottom = three_d ? "z0" : "bottom";
  if (platen)
    cfg.bcs.push_back({BcType::RigidPlaten, top, axial, kForce, {}, "ramp"});
  else
    cfg.bcs.push_back({BcType::Displacement, top, axial, -0.01, {}, "ramp"});
  cfg.bcs.push_back({BcType::Displacement, bottom, axial, 0.0, {}, ""});
  if (three_d) {
    cfg.bcs.push_back({BcType::Symmetry, "x0", 0, 0.0, {}, ""});
    cfg.bcs.push_back({BcType::Symmetry, "y0", 0, 0.0, {}, ""});
    cfg.bcs.push_back({BcType::Pressure, "x1", 0, 0.0, {}, ""});
  } else {
    cfg.bcs.push_back({BcType::Displacement, "bottom", 0, 0.0, {}, ""});
    cfg.bcs.push_back({BcType::Pressure, "lateral", 0, 0.0, {}, ""});
  }
  cfg.time.t_end = 2.0;
  return cfg;
}

/// A random state (u ~ 0.02, p ~ 0.05, rates a tenth of those), Dirichlet and tied entries set.
template <class Problem>
void random_state(Problem& problem, double t, std::vector<double>& y, std::vector<double>& ydot) {
  test::random_state(problem, t, 5, y, ydot);
}

/// Largest |FD − exact| over all entries for dF/dy + c_j dF/dẏ (`rate` false) or dF/dẏ
/// (`rate` true), and the largest exact entry.
template <class Problem>
std::pair<double, double> jacobian_error(Problem& problem, bool rate) {
  const double t = 1.3, cj = 3.0;
  std::vector<double> y, ydot;
  random_state(problem, t, y, ydot);
  const auto n = static_cast<std::size_t>(problem.size());
  const SparsityPattern& pattern = problem.pattern();
  std::vector<double> values(static_cast<std::size_t>(pattern.nnz())), rates(values.size());
  problem.jacobian(t, y.data(), ydot.data(), cj, values.data(), rates.data());
  const std::vector<double>& exact = rate ? rates : values;
  std::vector<double> Fp(n), Fm(n);
  double worst = 0.0, scale = 0.0;
  for (double v : exact) scale = std::max(scale, std::abs(v));
  for (std::size_t j = 0; j < n; ++j) {
    const double h = 1e-7;
    std::vector<double> yp = y, ym = y, vp = ydot, vm = ydot;
    if (!rate) {
      yp[j] += h;
      ym[j] -= h;
    }
    vp[j] += (rate ? 1.0 : cj) * h;
    vm[j] -= (rate ? 1.0 : cj) * h;
    problem.residual(t, yp.data(), vp.data(), Fp.data());
    problem.residual(t, ym.data(), vm.data(), Fm.data());
    for (std::size_t i = 0; i < n; ++i) {
      double fd = (Fp[i] - Fm[i]) / (2.0 * h);
      if (rate && problem.constrained()[i]) fd = 0.0;  // dF/dẏ is zero on held and tied rows
      const Index k = pattern.find(static_cast<Index>(i), static_cast<Index>(j));
      const double e = k >= 0 ? exact[static_cast<std::size_t>(k)] : 0.0;
      worst = std::max(worst, std::abs(fd - e));
    }
  }
  return {worst, scale};
}

TEST(RigidPlaten, SectionJacobianMatchesCentralDifferences) {
  const SectionMesh mesh = small_section();
  for (SectionModel model : {SectionModel::PlaneStrain, SectionModel::Axisymmetric})
    for (bool rate : {false, true}) {
      SectionProblem problem(mesh, model, platen_config(false, true));
      ASSERT_EQ(problem.platens().platens().size(), 1u);
      const auto [worst, scale] = jacobian_error(problem, rate);
      EXPECT_LT(worst, 1e-6 * scale)
          << to_string(model) << (rate ? " dF/dydot" : " dF/dy + cj dF/dydot") << ": worst "
          << worst << ", scale " << scale;
    }
}

TEST(RigidPlaten, TetrahedralJacobianMatchesCentralDifferences) {
  const Mesh mesh = test::box_mesh({1, 1, 2}, {1.0, 1.0, 1.0});
  for (bool rate : {false, true}) {
    BiphasicProblem problem(mesh, platen_config(true, true));
    const auto [worst, scale] = jacobian_error(problem, rate);
    EXPECT_LT(worst, 1e-6 * scale) << (rate ? "dF/dydot" : "dF/dy + cj dF/dydot") << ": worst "
                                   << worst << ", scale " << scale;
  }
}

/// At one state the platen problem's rows equal the displacement problem's: the force row is its
/// reaction minus P(t), the tie rows vanish (the state is rigid on the platen), every other row
/// is the same; the platen's own reaction is the same sum.
template <class Problem, class MeshT, class... Extra>
void expect_force_row_is_the_reaction(const MeshT& mesh, bool three_d, Extra... extra) {
  Problem with_platen(mesh, extra..., platen_config(three_d, true));
  Problem with_displacement(mesh, extra..., platen_config(three_d, false));
  const double t = 1.3;
  std::vector<double> y, ydot;
  random_state(with_displacement, t, y, ydot);  // the platen moves rigidly: −0.01 · ramp(t)
  std::vector<double> Fa(y.size()), Fb(y.size());
  with_platen.residual(t, y.data(), ydot.data(), Fa.data());
  with_displacement.residual(t, y.data(), ydot.data(), Fb.data());
  const std::string top = three_d ? "z1" : "top";
  const int axial = three_d ? 2 : 1;
  const double reaction = with_displacement.reactions(
      {top}, t, y.data(), ydot.data())[0][static_cast<std::size_t>(axial)];
  const double own =
      with_platen.reactions({top}, t, y.data(), ydot.data())[0][static_cast<std::size_t>(axial)];
  const RigidPlaten& platen = with_platen.platens().platens().at(0);
  const double force = kForce * 1.3 / 2.0;
  EXPECT_NEAR(with_platen.platens().force(0, t), force, 1e-15);
  EXPECT_NEAR(Fa[static_cast<std::size_t>(platen.master)], reaction - force,
              1e-12 * std::abs(reaction));
  EXPECT_NEAR(own, reaction, 1e-12 * std::abs(reaction));
  double scale = 0.0;
  for (double f : Fb) scale = std::max(scale, std::abs(f));
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (static_cast<Index>(i) == platen.master) continue;
    const bool tied =
        std::binary_search(platen.dofs.begin(), platen.dofs.end(), static_cast<Index>(i));
    if (tied)
      EXPECT_NEAR(Fa[i], 0.0, 1e-15) << "tie row " << i;
    else
      EXPECT_NEAR(Fa[i], Fb[i], 1e-13 * scale) << "row " << i;
  }
}

TEST(RigidPlaten, ForceRowIsTheReactionOfTheSameMotion) {
  expect_force_row_is_the_reaction<SectionProblem>(small_section(), false,
                                                   SectionModel::Axisymmetric);
  expect_force_row_is_the_reaction<SectionProblem>(small_section(), false,
                                                   SectionModel::PlaneStrain);
  expect_force_row_is_the_reaction<BiphasicProblem>(test::box_mesh({1, 1, 2}, {1.0, 1.0, 1.0}),
                                                    true);
}

TEST(RigidPlaten, PlatenAreaIsTheLoadedArea) {
  const SectionMesh mesh = small_section();
  SectionProblem axi(mesh, SectionModel::Axisymmetric, platen_config(false, true));
  SectionProblem planar(mesh, SectionModel::PlaneStrain, platen_config(false, true));
  EXPECT_NEAR(axi.platens().platens()[0].area, M_PI * 1.0 * 1.0, 1e-12);
  EXPECT_NEAR(planar.platens().platens()[0].area, 1.0, 1e-12);
  const Mesh box = test::box_mesh({1, 1, 2}, {1.0, 0.5, 1.0});
  BiphasicProblem three_d(box, platen_config(true, true));
  EXPECT_NEAR(three_d.platens().platens()[0].area, 0.5, 1e-12);
}

TEST(RigidPlaten, ApplyDirichletTiesThePlatenToItsMaster) {
  const SectionMesh mesh = small_section();
  SectionProblem problem(mesh, SectionModel::PlaneStrain, platen_config(false, true));
  std::vector<double> y(static_cast<std::size_t>(problem.size()), 0.0), ydot = y;
  const RigidPlaten& platen = problem.platens().platens()[0];
  y[static_cast<std::size_t>(platen.master)] = -0.3;
  ydot[static_cast<std::size_t>(platen.master)] = 0.7;
  problem.apply_dirichlet(0.5, y.data(), ydot.data());
  EXPECT_GT(platen.dofs.size(), 3u);
  for (Index i : platen.dofs) {
    EXPECT_EQ(y[static_cast<std::size_t>(i)], -0.3);
    EXPECT_EQ(ydot[static_cast<std::size_t>(i)], 0.7);
    EXPECT_EQ(problem.constrained()[static_cast<std::size_t>(i)], i == platen.master ? 0 : 1);
  }
}

TEST(RigidPlaten, RefusesAPlatenNodeHeldAlongItsComponent) {
  Config cfg = platen_config(false, true);
  cfg.bcs.push_back({BcType::Displacement, "lateral", 1, 0.0, {}, ""});  // holds the corner's u_y
  try {
    const SectionMesh mesh = small_section();
    SectionProblem problem(mesh, SectionModel::PlaneStrain, cfg);
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("boundary[0] (rigid_platen on 'top'): node"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("also held"), std::string::npos) << e.what();
  }
}

TEST(RigidPlaten, RefusesTwoPlatensSharingANode) {
  Config cfg = platen_config(false, true);
  cfg.bcs.push_back({BcType::RigidPlaten, "lateral", 0, 0.01, {}, ""});
  try {
    const SectionMesh mesh = small_section();
    SectionProblem problem(mesh, SectionModel::PlaneStrain, cfg);
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a node can belong to one rigid platen only"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace biphasic
