// The two-dimensional element kernel (plane strain and axisymmetric P2/P1 triangles): both
// Jacobian blocks against central differences of the residual, block by block, for every
// registered pair of laws and every stabilisation, also on an element touching the axis; the
// momentum rows against the gradient of the stored energy (an independent check of the hoop
// term and of the 2πR measure); and the measure itself against Pappus' theorem.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "biphasic/material/material_laws.hpp"
#include "biphasic/mesh/mesh.hpp"
#include "biphasic/physics/section_element.hpp"

namespace biphasic {
namespace {

/// A distorted 6-node triangle with one curved edge, its corners at (r0 + …, z), size `s` [mm].
Eigen::Matrix<double, 6, 2> distorted_triangle(double r0, double s) {
  Eigen::Matrix<double, 3, 2> V;
  V << r0 + 0.1 * s, 0.05 * s, r0 + 1.2 * s, 0.2 * s, r0 + 0.35 * s, 1.1 * s;
  Eigen::Matrix<double, 6, 2> X;
  X.topRows<3>() = V;
  for (int e = 0; e < 3; ++e)
    X.row(3 + e) = 0.5 * (V.row(kTriEdges[e][0]) + V.row(kTriEdges[e][1]));
  X(4, 0) += 0.04 * s;  // curve edge (1, 2)
  return X;
}

/// A triangle with its edge (0, 2) on the axis R = 0, of size `s` [mm].
Eigen::Matrix<double, 6, 2> axis_triangle(double s) {
  Eigen::Matrix<double, 6, 2> X;
  X << 0.0, 0.0, 0.9 * s, 0.3 * s, 0.0, s, 0.45 * s, 0.15 * s, 0.45 * s, 0.65 * s, 0.0, 0.5 * s;
  return X;
}

/// A random state with displacement gradients of order `amplitude`, pressures of order 0.1 MPa;
/// displacements of the nodes at R = 0 are radially zero (the axis condition) when `axis`.
void random_state(unsigned seed, double amplitude, double size,
                  const Eigen::Matrix<double, 6, 2>& X, bool axis, SectionElementVector& y,
                  SectionElementVector& ydot) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (int i = 0; i < 12; ++i) y(i) = amplitude * size * d(gen);
  for (int i = 12; i < 15; ++i) y(i) = 0.1 * d(gen);
  for (int i = 0; i < 15; ++i) ydot(i) = 0.01 * (i < 12 ? size : 1.0) * d(gen);
  if (axis)
    for (int a = 0; a < 6; ++a)
      if (X(a, 0) == 0.0) y(2 * a) = ydot(2 * a) = 0.0;
}

struct Block {
  const char* name;
  int r0, nr, c0, nc;
};
const Block kBlocks[] = {
    {"u-u", 0, 12, 0, 12}, {"u-p", 0, 12, 12, 3}, {"p-u", 12, 3, 0, 12}, {"p-p", 12, 3, 12, 3}};

/// Relative error per block of ∂R/∂y (rate = false) or ∂R/∂ẏ (rate = true) against central
/// differences with steps ε and ε/2 (ε relative to the element size for displacements).
template <class Solid, class Permeability>
std::vector<std::pair<double, double>> block_errors(const std::vector<SectionPointGeometry>& geo,
                                                    const Solid& solid, const Permeability& k,
                                                    const ElementCoefficients& c,
                                                    const SectionElementVector& y,
                                                    const SectionElementVector& ydot, double size,
                                                    bool rate) {
  SectionElementOutput exact, plus, minus;
  section_element(geo, solid, k, c, y, ydot, true, exact);
  const SectionElementMatrix& J = rate ? exact.dfdydot : exact.dfdy;
  auto difference = [&](double eps) {
    SectionElementMatrix D;
    for (int j = 0; j < kSectionElementDofs; ++j) {
      const double h = j < 12 ? eps * size : eps;
      SectionElementVector yp = y, ym = y, vp = ydot, vm = ydot;
      (rate ? vp : yp)(j) += h;
      (rate ? vm : ym)(j) -= h;
      section_element(geo, solid, k, c, yp, vp, false, plus);
      section_element(geo, solid, k, c, ym, vm, false, minus);
      D.col(j) = (plus.residual - minus.residual) / (2.0 * h);
    }
    return SectionElementMatrix(D - J);
  };
  const SectionElementMatrix E1 = difference(2e-4), E2 = difference(1e-4);
  std::vector<std::pair<double, double>> errors;
  for (const Block& b : kBlocks) {
    const double scale = J.block(b.r0, b.c0, b.nr, b.nc).norm();
    if (scale == 0.0) {
      // A block that is exactly zero must stay zero under differences (to round-off).
      errors.emplace_back(E1.block(b.r0, b.c0, b.nr, b.nc).norm() > 1e-8 ? 1.0 : 0.0, 0.0);
      continue;
    }
    errors.emplace_back(E1.block(b.r0, b.c0, b.nr, b.nc).norm() / scale,
                        E2.block(b.r0, b.c0, b.nr, b.nc).norm() / scale);
  }
  return errors;
}

/// Every block's error is either at round-off (below 1e-7) or pure truncation error: falling as
/// ε² (ratio ≈ 4 per halving) and below 1e-3 at ε/2.
void expect_second_order(const std::vector<std::pair<double, double>>& errors,
                         const std::string& label) {
  for (std::size_t n = 0; n < errors.size(); ++n) {
    const auto [e1, e2] = errors[n];
    if (e1 < 1e-7) continue;
    EXPECT_LT(e2, 1e-3) << label << " " << kBlocks[n].name;
    EXPECT_NEAR(e1 / e2, 4.0, 0.4)
        << label << " " << kBlocks[n].name << " e1=" << e1 << " e2=" << e2;
  }
}

/// A parameter value off its default and inside its bounds, so every term of a law acts.
double exercised_value(const LawParameter& p) {
  const auto within = [&p](double x) {
    const ParameterBounds& b = p.bounds;
    return (!b.min || (b.min_open ? x > *b.min : x >= *b.min)) &&
           (!b.max || (b.max_open ? x < *b.max : x <= *b.max));
  };
  const double x = 1.37 * p.default_value + 0.3;
  return within(x) ? x : 1.37 * p.default_value + 0.01;
}

/// Every registered pair of laws, with its parameters moved off their defaults.
std::vector<std::pair<std::string, MaterialLaws>> all_law_pairs() {
  std::vector<std::pair<std::string, MaterialLaws>> out;
  for (const LawDescription& solid : material_law_families()[0].laws) {
    for (const LawDescription& permeability : material_law_families()[1].laws) {
      MaterialConfig m;
      m.solid_law = solid.name;
      m.permeability_law = permeability.name;
      for (const auto& family : material_law_families())
        for (const auto& law : family.laws)
          for (const auto& p : law.parameters) m.set(p.name, exercised_value(p));
      out.emplace_back(solid.name + " + " + permeability.name, make_material_laws(m));
    }
  }
  return out;
}

struct Case {
  ElementCoefficients c;
  const char* name;
};
// Plain, GLS, flux perturbation, and the conservative volume rate of backward Euler with GLS.
const Case kCases[] = {{{0.0, 0.0, 0.0}, "plain"},
                       {{2.5, 0.0, 0.0}, "gls"},
                       {{0.0, 0.35, 0.0}, "flux_perturbation"},
                       {{2.5, 0.0, 0.4}, "gls, conservative rate"},
                       {{0.0, 0.35, 0.4}, "flux_perturbation, conservative rate"},
                       // need-following: c_e(J) = 2.5 k(1)/k(J) − 1, β(J) = 0.35 − 0.3 k(J), on
                       {{2.5, 0.0, 0.0, 1.0, 0.0}, "gls_minimal"},
                       {{0.0, 0.35, 0.0, 0.0, 0.3}, "flux_perturbation_minimal"}};

void expect_consistent_jacobians(SectionModel model, const Eigen::Matrix<double, 6, 2>& X,
                                 double size, bool axis, const std::string& where) {
  std::vector<SectionPointGeometry> geo;
  section_point_geometry(X, model, geo);
  SectionElementVector y, ydot;
  random_state(11, 0.08, size, X, axis, y, ydot);
  int checked = 0;
  for (const auto& [name, laws] : all_law_pairs()) {
    for (const Case& c : kCases) {
      std::visit(
          [&](const auto& s, const auto& k) {
            const std::string label = to_string(model) + ", " + where + ", " + name + ", " + c.name;
            expect_second_order(block_errors(geo, s, k, c.c, y, ydot, size, false),
                                label + ", dF/dy");
            expect_second_order(block_errors(geo, s, k, c.c, y, ydot, size, true),
                                label + ", dF/dydot");
          },
          laws.solid, laws.permeability);
      ++checked;
    }
  }
  EXPECT_EQ(checked, static_cast<int>(std::size(kCases) * std::variant_size_v<AnySolidLaw> *
                                      std::variant_size_v<AnyPermeabilityLaw>));
}

TEST(SectionElement, PlaneStrainJacobianMatchesCentralDifferencesForEveryLawAndStabilisation) {
  expect_consistent_jacobians(SectionModel::PlaneStrain, distorted_triangle(0.0, 1.0), 1.0, false,
                              "interior");
}

TEST(SectionElement, AxisymmetricJacobianMatchesCentralDifferencesForEveryLawAndStabilisation) {
  expect_consistent_jacobians(SectionModel::Axisymmetric, distorted_triangle(0.6, 1.0), 1.0, false,
                              "off the axis");
}

// On the axis the hoop terms N_a/R are largest (R → 0 at the quadrature points of a small
// element): the Jacobian must hold there too, at any element size.
TEST(SectionElement, AxisymmetricJacobianHoldsOnTheAxis) {
  for (double s : {1.0, 1e-3})
    expect_consistent_jacobians(SectionModel::Axisymmetric, axis_triangle(s), s, true,
                                "on the axis, size " + std::to_string(s) + " mm");
}

// Without pressure and rates, the momentum rows are the gradient of the stored energy
// Π(u) = Σ_q w_q Ψ(F_q), evaluated with the law's own energy() and an F built here from the
// displacement field (u_r/R from the nodal values and shape functions): an independent check of
// the directions ∂F/∂u_d, the hoop term and the measure.
template <class Solid>
void expect_residual_is_energy_gradient(SectionModel model, const Eigen::Matrix<double, 6, 2>& X,
                                        const Solid& solid) {
  std::vector<SectionPointGeometry> geo;
  section_point_geometry(X, model, geo);
  SectionElementVector y, ydot;
  random_state(5, 0.1, 1.0, X, false, y, ydot);
  y.tail<3>().setZero();
  ydot.setZero();
  auto energy = [&](const SectionElementVector& state) {
    double total = 0.0;
    for (std::size_t q = 0; q < geo.size(); ++q) {
      Mat3 F = Mat3::Identity();
      double ur = 0.0;
      for (int a = 0; a < 6; ++a) {
        for (int i = 0; i < 2; ++i)
          for (int J = 0; J < 2; ++J) F(i, J) += state(2 * a + i) * geo[q].dN(a, J);
        ur += state(2 * a) * geo[q].N(a);
      }
      if (model == SectionModel::Axisymmetric) {
        double R = 0.0;
        for (int a = 0; a < 6; ++a) R += X(a, 0) * geo[q].N(a);
        F(2, 2) += ur / R;
      }
      total += geo[q].weight * solid.energy(F);
    }
    return total;
  };
  SectionElementOutput out;
  section_element(geo, solid, ConstantPermeability{1e-3}, ElementCoefficients{}, y, ydot, false,
                  out);
  for (int d = 0; d < 12; ++d) {
    const double h = 1e-6;
    SectionElementVector yp = y, ym = y;
    yp(d) += h;
    ym(d) -= h;
    const double gradient = (energy(yp) - energy(ym)) / (2.0 * h);
    EXPECT_NEAR(out.residual(d), gradient, 1e-7 * (1.0 + std::abs(gradient)))
        << to_string(model) << " dof " << d;
  }
}

TEST(SectionElement, MomentumRowsAreTheGradientOfTheStoredEnergy) {
  for (SectionModel model : {SectionModel::PlaneStrain, SectionModel::Axisymmetric}) {
    expect_residual_is_energy_gradient(model, distorted_triangle(0.3, 1.0), NeoHookean{0.3, 0.7});
    expect_residual_is_energy_gradient(model, distorted_triangle(0.3, 1.0),
                                       HolmesMowSolid{1.2, 0.2, 0.4});
  }
}

// The axisymmetric measure integrates 2πR over the triangle: for a straight triangle the
// weights sum to 2π R̄ A (Pappus), R̄ the centroid's radius; plane strain gives A (1 mm deep).
TEST(SectionElement, MeasureIsTheVolumeOfRevolution) {
  Eigen::Matrix<double, 6, 2> X = distorted_triangle(0.5, 2.0);
  for (int e = 0; e < 3; ++e)
    X.row(3 + e) = 0.5 * (X.row(kTriEdges[e][0]) + X.row(kTriEdges[e][1]));
  const double area =
      0.5 * ((X(1, 0) - X(0, 0)) * (X(2, 1) - X(0, 1)) - (X(2, 0) - X(0, 0)) * (X(1, 1) - X(0, 1)));
  const double centroid_r = (X(0, 0) + X(1, 0) + X(2, 0)) / 3.0;
  for (SectionModel model : {SectionModel::PlaneStrain, SectionModel::Axisymmetric}) {
    std::vector<SectionPointGeometry> geo;
    section_point_geometry(X, model, geo);
    double sum = 0.0;
    for (const auto& g : geo) sum += g.weight;
    const double expected =
        model == SectionModel::Axisymmetric ? 2.0 * std::numbers::pi * centroid_r * area : area;
    EXPECT_NEAR(sum, expected, 1e-13 * expected) << to_string(model);
  }
}

// Homogeneous radial expansion u_r = εR, u_z = 0: F = diag(1 + ε, 1, 1 + ε), J = (1 + ε)², so
// with a uniform pressure rate and no flow the mass rows sum to J̇ times the volume.
TEST(SectionElement, RadialExpansionHasTheHoopStretch) {
  const Eigen::Matrix<double, 6, 2> X = distorted_triangle(0.8, 1.0);
  std::vector<SectionPointGeometry> geo;
  section_point_geometry(X, SectionModel::Axisymmetric, geo);
  const double eps = 0.05, rate = 0.01;  // ε and ε̇ [1/s]
  SectionElementVector y = SectionElementVector::Zero(), ydot = SectionElementVector::Zero();
  for (int a = 0; a < 6; ++a) {
    y(2 * a) = eps * X(a, 0);
    ydot(2 * a) = rate * X(a, 0);
  }
  SectionElementOutput out;
  section_element(geo, NeoHookean{0.2, 0.5}, ConstantPermeability{1e-3}, ElementCoefficients{}, y,
                  ydot, false, out);
  double volume = 0.0;
  for (const auto& g : geo) volume += g.weight;
  const double Jdot = 2.0 * (1.0 + eps) * rate;
  EXPECT_NEAR(out.residual.tail<3>().sum(), Jdot * volume, 1e-12 * Jdot * volume);
}

}  // namespace
}  // namespace biphasic
