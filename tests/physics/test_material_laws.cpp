// The material-law layer: the registry, the Neo-Hookean point response, and the dk/dJ part of
// the element Jacobian, checked with a test-only permeability law whose derivative is not zero.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "biphasic/material/material_laws.hpp"
#include "element_fixture.hpp"

namespace biphasic {
namespace {

/// Test-only law k(J) = k₀ J², dk/dJ = 2 k₀ J [mm⁴ N⁻¹ s⁻¹].
struct QuadraticPermeability {
  double k0 = 1e-2;
  double permeability(double J) const { return k0 * J * J; }
  double permeability_derivative(double J) const { return 2.0 * k0 * J; }
};
static_assert(PermeabilityLaw<QuadraticPermeability>);

/// The same k(J) with the derivative left out: its Jacobian must fail the check below.
struct QuadraticPermeabilityWithoutDerivative : QuadraticPermeability {
  double permeability_derivative(double /*J*/) const { return 0.0; }
};

struct Block {
  const char* name;
  int r0, nr, c0, nc;
};
const Block kBlocks[] = {
    {"u-u", 0, 30, 0, 30}, {"u-p", 0, 30, 30, 4}, {"p-u", 30, 4, 0, 30}, {"p-p", 30, 4, 30, 4}};

/// Relative error per block of the Jacobian ∂R/∂y with the permeability law `Law` and the solid
/// law `solid` against central differences with steps ε and ε/2.
template <class Law, class Solid = NeoHookean>
std::vector<std::pair<double, double>> block_errors(const Law& law, const ElementCoefficients& c,
                                                    const Solid& solid = NeoHookean{0.2, 0.5}) {
  const std::vector<PointGeometry> geo = test::distorted_tet_geometry();
  ElementVector y, ydot;
  test::random_state(7, 0.08, y, ydot);
  ElementOutput exact, plus, minus;
  biphasic_element(geo, solid, law, c, y, ydot, true, exact);
  auto difference = [&](double eps) {
    ElementMatrix D;
    for (int j = 0; j < kElementDofs; ++j) {
      ElementVector yp = y, ym = y;
      yp(j) += eps;
      ym(j) -= eps;
      biphasic_element(geo, solid, law, c, yp, ydot, false, plus);
      biphasic_element(geo, solid, law, c, ym, ydot, false, minus);
      D.col(j) = (plus.residual - minus.residual) / (2.0 * eps);
    }
    return ElementMatrix(D - exact.dfdy);
  };
  const ElementMatrix E1 = difference(1e-3), E2 = difference(5e-4);
  std::vector<std::pair<double, double>> errors;
  for (const Block& b : kBlocks) {
    const double scale = std::max(1e-12, exact.dfdy.block(b.r0, b.c0, b.nr, b.nc).norm());
    errors.emplace_back(E1.block(b.r0, b.c0, b.nr, b.nc).norm() / scale,
                        E2.block(b.r0, b.c0, b.nr, b.nc).norm() / scale);
  }
  return errors;
}

/// Every block's error below 1e-5 at ε/2 and falling as ε² (ratio ≈ 4 per halving) unless at
/// round-off; `label` names the case in failures.
void expect_second_order(const std::vector<std::pair<double, double>>& errors,
                         const std::string& label) {
  for (std::size_t n = 0; n < errors.size(); ++n) {
    const auto [e1, e2] = errors[n];
    EXPECT_LT(e2, 1e-5) << label << " " << kBlocks[n].name;
    if (e1 > 1e-9) {
      EXPECT_NEAR(e1 / e2, 4.0, 0.4)
          << label << " " << kBlocks[n].name << " e1=" << e1 << " e2=" << e2;
    }
  }
}

/// Stabilisation and volume-rate coefficients of one case, with a name for the test list.
struct Coefficients {
  ElementCoefficients c;
  const char* name;
  bool gls_term = false;  ///< the GLS term is on at the test's state (c_e(J) > 0)
  friend void PrintTo(const Coefficients& x, std::ostream* os) { *os << x.name; }
};
class PermeabilityDerivative : public ::testing::TestWithParam<Coefficients> {};

// Every block converges as ε² (ratio ≈ 4 per halving) or is at round-off.
TEST_P(PermeabilityDerivative, JacobianMatchesCentralDifferencesBlockByBlock) {
  expect_second_order(block_errors(QuadraticPermeability{}, GetParam().c), GetParam().name);
}

// Without the dk/dJ term the p-u block is wrong at O(1), and with GLS, whose c_e = h²/(4k(J))
// follows k, the u-u block too: the check above can see both.
TEST_P(PermeabilityDerivative, MissingDerivativeIsDetected) {
  const auto errors = block_errors(QuadraticPermeabilityWithoutDerivative{}, GetParam().c);
  EXPECT_GT(errors[2].second, 1e-3);  // p-u
  EXPECT_LT(errors[3].second, 1e-5);  // p-p does not involve dk/dJ
  if (GetParam().gls_term) {
    EXPECT_GT(errors[0].second, 1e-4) << "u-u";
  } else {
    EXPECT_LT(errors[0].second, 1e-5) << "u-u";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Stabilisations, PermeabilityDerivative,
    ::testing::Values(Coefficients{{0.0, 0.0, 0.0}, "plain"},
                      Coefficients{{2.5, 0.0, 0.0}, "gls", true},
                      Coefficients{{0.0, 0.35, 0.0}, "flux_perturbation"},
                      Coefficients{{2.5, 0.0, 5.0}, "gls_conservative", true},
                      // need-following, k = 0.01 J²: c_e = 2.5/J² − 1 > 0, and
                      // 2.5/J² − 10 < 0 (clipped); β = 0.35 − 0.1 J² > 0, 0.35 − J² < 0
                      Coefficients{{2.5, 0.0, 0.0, 1.0, 0.0}, "gls_minimal", true},
                      Coefficients{{2.5, 0.0, 0.0, 10.0, 0.0}, "gls_minimal_clipped"},
                      Coefficients{{0.0, 0.35, 0.0, 0.0, 10.0}, "flux_minimal"},
                      Coefficients{{0.0, 0.35, 0.0, 0.0, 100.0}, "flux_minimal_clipped"}),
    [](const auto& param_info) { return param_info.param.name; });

// Under an affine displacement J is the same at every quadrature point, so the GLS coefficient
// h²/(4k(J)) of a strain-dependent law equals that of a constant law k = k(J) with c_e scaled by
// k(1)/k(J): the two residuals agree to round-off (the Darcy terms agree as well).
TEST(MaterialLaws, GlsCoefficientFollowsThePermeabilityOfTheState) {
  const std::vector<PointGeometry> geo = test::distorted_tet_geometry();
  const Eigen::Matrix<double, 10, 3> X = test::distorted_tet();
  Mat3 H;
  H << -0.12, 0.02, 0.01, 0.03, -0.08, 0.0, 0.01, -0.02, -0.1;
  ElementVector y = ElementVector::Zero(), ydot = ElementVector::Zero();
  for (int a = 0; a < 10; ++a) {
    y.segment<3>(3 * a) = H * X.row(a).transpose();
    ydot.segment<3>(3 * a) = 0.3 * H * X.row(a).transpose();
  }
  y.tail<4>() << 0.01, -0.02, 0.03, 0.005;
  const double J = (Mat3::Identity() + H).determinant();
  const QuadraticPermeability law;
  const double c_ref = 2.5;
  ElementOutput with_law, with_constant;
  const NeoHookean solid{0.2, 0.5};
  biphasic_element(geo, solid, law, ElementCoefficients{c_ref, 0.0, 0.0}, y, ydot, false, with_law);
  const double k_J = law.permeability(J), k_1 = law.permeability(1.0);
  biphasic_element(geo, solid, ConstantPermeability{k_J},
                   ElementCoefficients{c_ref * k_1 / k_J, 0.0, 0.0}, y, ydot, false, with_constant);
  EXPECT_LT((with_law.residual - with_constant.residual).norm(), 1e-13 * with_law.residual.norm());
  // ... and differs from the coefficient frozen at k(1) by the ratio k(1)/k(J) ≈ 1.9.
  ElementOutput frozen;
  biphasic_element(geo, solid, ConstantPermeability{k_J}, ElementCoefficients{c_ref, 0.0, 0.0}, y,
                   ydot, false, frozen);
  EXPECT_GT((with_law.residual - frozen.residual).head<30>().norm(),
            1e-3 * with_law.residual.head<30>().norm());
}

TEST(MaterialLaws, ConstantPermeabilityIsConstant) {
  const ConstantPermeability k{3e-3};
  EXPECT_EQ(k.permeability(0.7), 3e-3);
  EXPECT_EQ(k.permeability(1.4), 3e-3);
  EXPECT_EQ(k.permeability_derivative(0.7), 0.0);
}

TEST(MaterialLaws, RegistryBuildsTheCaseMaterial) {
  const MaterialLaws laws = make_material_laws([] {
    MaterialConfig m;
    m.set("permeability", 2e-3);
    return m;
  }());
  ASSERT_TRUE(std::holds_alternative<NeoHookean>(laws.solid));
  EXPECT_EQ(std::get<NeoHookean>(laws.solid).lambda, 0.2);
  EXPECT_EQ(std::get<NeoHookean>(laws.solid).mu, 0.5);
  EXPECT_DOUBLE_EQ(laws.p_wave_modulus(), 1.2);
  EXPECT_EQ(laws.reference_permeability(), 2e-3);
}

// The templated kernel with the laws equals the ElementParameters form, bit for bit.
TEST(MaterialLaws, ParameterFormCallsTheLaws) {
  const std::vector<PointGeometry> geo = test::distorted_tet_geometry();
  ElementParameters p;
  p.material = {0.3, 0.4};
  p.permeability = 4e-3;
  p.gls_c = 1.5;
  ElementVector y, ydot;
  test::random_state(3, 0.05, y, ydot);
  ElementOutput a, b;
  biphasic_element(geo, p, y, ydot, true, a);
  biphasic_element(geo, p.material, ConstantPermeability{4e-3}, p, y, ydot, true, b);
  EXPECT_EQ(a.residual, b.residual);
  EXPECT_EQ(a.dfdy, b.dfdy);
  EXPECT_EQ(a.dfdydot, b.dfdydot);
}

// stiffness(b, G, a, i, e, k) = ∇₀N_a,J A_iJkL ∇₀N_e,L, with A from tangent_apply, and the
// response's stress is the law's first Piola stress.
TEST(NeoHookean, PointResponseContractsTheTangent) {
  const NeoHookean m{0.2, 0.5};
  Mat3 F;
  F << 1.1, 0.1, -0.05, 0.02, 0.93, 0.08, -0.04, 0.06, 1.05;
  const double J = F.determinant();
  const Mat3 FinvT = F.inverse().transpose();
  ShapeGradients dN;
  for (int a = 0; a < 10; ++a)
    for (int j = 0; j < 3; ++j) dN(a, j) = 0.1 * (a + 1) * (j - 1.2) + 0.05 * a * a * (j == 1);
  const ShapeGradients b = dN * F.inverse();
  const ShapeProducts G = dN * dN.transpose();
  const NeoHookean::Tangent r = m.response(F, J);
  EXPECT_LT((r.first_piola(F, FinvT) - m.first_piola(F)).norm(), 1e-15);
  for (int e = 0; e < 10; ++e)
    for (int k = 0; k < 3; ++k) {
      const Mat3 H = Vec3::Unit(k) * dN.row(e);  // H_kL = ∇₀N_e,L
      const Mat3 AH = m.tangent_apply(F, H);
      for (int a = 0; a < 10; ++a)
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR(r.stiffness(b, G, a, i, e, k), AH.row(i).dot(dN.row(a)), 1e-13);
    }
}

}  // namespace
}  // namespace biphasic

namespace biphasic {
namespace {

const HolmesMowPermeability kHolmesMow{2e-3, 0.2, 1.5, 4.0};
const ExponentialPermeability kExponential{2e-3, 0.2, 3.0};

/// dk/dJ of `law` against a central difference of k at J, relative; the step shrinks with the
/// distance to full compaction J = φ₀ = 0.2, where k varies fastest.
template <class Law>
double derivative_error(const Law& law, double J) {
  const double h = 1e-6 * (J - 0.2);
  const double fd = (law.permeability(J + h) - law.permeability(J - h)) / (2.0 * h);
  return std::abs(law.permeability_derivative(J) - fd) / std::abs(fd);
}

// Closed-form values at chosen J, derivative against differences, k(1) = k0, and J <= phi0
// refused with a domain_error naming phi0.
TEST(StrainDependentPermeability, HolmesMowValuesAndDerivative) {
  EXPECT_DOUBLE_EQ(kHolmesMow.permeability(1.0), 2e-3);
  // J = 0.6: ((0.6 − 0.2)/0.8)^1.5 exp(4 (0.36 − 1)/2) = 0.5^1.5 e^−1.28.
  EXPECT_NEAR(kHolmesMow.permeability(0.6), 2e-3 * std::pow(0.5, 1.5) * std::exp(-1.28), 1e-18);
  // J = 1.2: (1/0.8)^1.5 exp(2 · 0.44).
  EXPECT_NEAR(kHolmesMow.permeability(1.2), 2e-3 * std::pow(1.25, 1.5) * std::exp(0.88), 1e-17);
  for (double J : {0.25, 0.5, 0.9, 1.0, 1.1, 1.5}) EXPECT_LT(derivative_error(kHolmesMow, J), 1e-7);
  EXPECT_THROW(kHolmesMow.permeability(0.2), std::domain_error);
  EXPECT_THROW(kHolmesMow.permeability_derivative(0.1), std::domain_error);
  try {
    kHolmesMow.permeability(0.15);
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("phi0 = 0.2"), std::string::npos) << e.what();
  }
}

TEST(StrainDependentPermeability, ExponentialValuesAndDerivative) {
  EXPECT_DOUBLE_EQ(kExponential.permeability(1.0), 2e-3);
  // J = 0.6: exp(3 · (−0.4)/0.4) = e^−3.
  EXPECT_NEAR(kExponential.permeability(0.6), 2e-3 * std::exp(-3.0), 1e-18);
  // Small strain: exponent ≈ M ε/(1 − φ0).
  const double eps = 1e-4;
  EXPECT_NEAR(std::log(kExponential.permeability(1.0 + eps) / 2e-3), 3.0 * eps / 0.8, 1e-7);
  for (double J : {0.25, 0.5, 0.9, 1.0, 1.1, 1.5})
    EXPECT_LT(derivative_error(kExponential, J), 1e-7);
  EXPECT_THROW(kExponential.permeability(0.2), std::domain_error);
}

// Lai & Mow: k0 exp(M (J - 1)), positive at every J > 0 (no pore closure).
TEST(StrainDependentPermeability, LaiMowValuesAndDerivative) {
  const LaiMowPermeability law{2e-3, 3.0};
  EXPECT_DOUBLE_EQ(law.permeability(1.0), 2e-3);
  EXPECT_NEAR(law.permeability(0.6), 2e-3 * std::exp(-1.2), 1e-18);
  EXPECT_NEAR(law.permeability(1.5), 2e-3 * std::exp(1.5), 1e-17);
  for (double J : {0.25, 0.5, 0.9, 1.0, 1.1, 1.5}) EXPECT_LT(derivative_error(law, J), 1e-7);
  EXPECT_GT(law.permeability(0.05), 0.0);
}

// The element Jacobian with each strain-dependent law, block by block against central
// differences (the state's J lies in about [0.8, 1.2], far from phi0 = 0.2).
TEST(StrainDependentPermeability, ElementJacobianMatchesCentralDifferences) {
  // The last two: the need-following coefficients, on over the state's J (k(1) = 2e-3;
  // c_e = 2.5 k(1)/k(J) − 0.1 and β = 0.35 − 10 k(J) stay positive).
  const ElementCoefficients cases[] = {{0.0, 0.0, 0.0},
                                       {2.5, 0.0, 0.0},
                                       {0.0, 0.35, 0.0},
                                       {2.5, 0.0, 0.0, 0.1, 0.0},
                                       {0.0, 0.35, 0.0, 0.0, 10.0}};
  for (const ElementCoefficients& c : cases) {
    expect_second_order(block_errors(kHolmesMow, c), "holmes_mow");
    expect_second_order(block_errors(kExponential, c), "exponential");
  }
}

/// The Holmes–Mow solid with the tangent of β = 0 (and the true stress): a wrong Jacobian.
struct HolmesMowWithFlatTangent {
  HolmesMowSolid law;
  double p_wave_modulus() const { return law.p_wave_modulus(); }
  HolmesMowSolid::Response response(const Mat3& F, double J) const {
    HolmesMowSolid flat = law;
    flat.beta = 0.0;
    HolmesMowSolid::Response r = flat.response(F, J);
    r.tau = law.response(F, J).tau;
    return r;
  }
};
static_assert(SolidLaw<HolmesMowWithFlatTangent>);

// The element Jacobian with the Holmes–Mow solid, with constant and Holmes–Mow permeability,
// without stabilisation, with GLS (incremental and conservative volume rate) and with the flux
// perturbation, block by block against central differences; the same check fails with the
// tangent of β = 0.
TEST(HolmesMowSolid, ElementJacobianMatchesCentralDifferences) {
  const HolmesMowSolid solid{1.2, 0.25, 0.9};
  const ElementCoefficients cases[] = {
      {0.0, 0.0, 0.0}, {2.5, 0.0, 0.0}, {2.5, 0.0, 5.0}, {0.0, 0.35, 0.0}};
  const char* names[] = {"plain", "gls", "gls_conservative", "flux_perturbation"};
  for (std::size_t n = 0; n < std::size(cases); ++n) {
    const std::string name = names[n];
    expect_second_order(block_errors(ConstantPermeability{2e-3}, cases[n], solid),
                        "constant k, " + name);
    expect_second_order(block_errors(kHolmesMow, cases[n], solid), "holmes_mow k, " + name);
  }
  const auto wrong = block_errors(kHolmesMow, cases[1], HolmesMowWithFlatTangent{solid});
  EXPECT_GT(wrong[0].second, 1e-3);  // u-u
  EXPECT_LT(wrong[3].second, 1e-5);  // p-p
}

TEST(StrainDependentPermeability, RegistryBuildsTheChosenLaw) {
  MaterialConfig m;
  m.set("permeability", 3e-3);
  m.set("solid_fraction", 0.25);
  m.set("permeability_kappa", 2.0);
  m.set("permeability_M", 5.0);
  m.permeability_law = "holmes_mow";
  const MaterialLaws hm = make_material_laws(m);
  ASSERT_TRUE(std::holds_alternative<HolmesMowPermeability>(hm.permeability));
  const auto& h = std::get<HolmesMowPermeability>(hm.permeability);
  EXPECT_EQ(h.k0, 3e-3);
  EXPECT_EQ(h.phi0, 0.25);
  EXPECT_EQ(h.kappa, 2.0);
  EXPECT_EQ(h.M, 5.0);
  EXPECT_EQ(hm.reference_permeability(), 3e-3);
  m.permeability_law = "exponential";
  const MaterialLaws ex = make_material_laws(m);
  ASSERT_TRUE(std::holds_alternative<ExponentialPermeability>(ex.permeability));
  EXPECT_EQ(std::get<ExponentialPermeability>(ex.permeability).M, 5.0);
}

// Every registered law builds itself from exactly the parameters it declares: reading an
// undeclared one would fail at run time for want of a default, and a declared one left unread
// would be a case-file key without effect.
template <class Variant>
void expect_laws_read_what_they_declare() {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (
        [&] {
          using Law = std::variant_alternative_t<I, Variant>;
          const LawDescription d = Law::describe();
          std::set<std::string> declared, read;
          for (const LawParameter& p : d.parameters) declared.insert(p.name);
          EXPECT_EQ(declared.size(), d.parameters.size()) << d.name << " repeats a parameter";
          (void)Law::from_parameters([&](const std::string& name) {
            read.insert(name);
            return find_law_parameter(name)->default_value;
          });
          EXPECT_EQ(read, declared) << d.name;
        }(),
        ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>{});
}

TEST(MaterialLawRegistry, EachLawReadsExactlyTheParametersItDeclares) {
  expect_laws_read_what_they_declare<AnySolidLaw>();
  expect_laws_read_what_they_declare<AnyPermeabilityLaw>();
}

/// A value of a declared parameter away from its default (so that every term of a law is
/// active, e.g. M > 0), inside its bounds: 1.37 × default + 0.3, or + 0.01 where that leaves
/// them.
double exercised_value(const LawParameter& p) {
  const auto within = [&p](double x) {
    const ParameterBounds& b = p.bounds;
    return (!b.min || (b.min_open ? x > *b.min : x >= *b.min)) &&
           (!b.max || (b.max_open ? x < *b.max : x <= *b.max));
  };
  const double x = 1.37 * p.default_value + 0.3;
  return within(x) ? x : 1.37 * p.default_value + 0.01;
}

// Every registered pair of laws, built from its declared parameters, has an element Jacobian
// that matches central differences block by block, without stabilisation, with GLS and with
// the flux perturbation: a newly registered law is checked here without a test of its own.
TEST(MaterialLawRegistry, EveryPairOfLawsHasAConsistentJacobian) {
  const ParameterSource source = [](const std::string& name) {
    return exercised_value(*find_law_parameter(name));
  };
  const ElementCoefficients cases[] = {{0.0, 0.0, 0.0}, {2.5, 0.0, 0.0}, {0.0, 0.35, 0.0}};
  const char* names[] = {"plain", "gls", "flux_perturbation"};
  int pairs = 0;
  for (const LawDescription& solid : material_law_families()[0].laws) {
    for (const LawDescription& permeability : material_law_families()[1].laws) {
      MaterialConfig m;
      m.solid_law = solid.name;
      m.permeability_law = permeability.name;
      for (const auto& family : material_law_families()) {
        for (const auto& law : family.laws) {
          for (const auto& p : law.parameters) m.set(p.name, source(p.name));
        }
      }
      const MaterialLaws laws = make_material_laws(m);
      for (std::size_t n = 0; n < std::size(cases); ++n) {
        std::visit(
            [&](const auto& s, const auto& k) {
              expect_second_order(block_errors(k, cases[n], s),
                                  solid.name + " + " + permeability.name + ", " + names[n]);
            },
            laws.solid, laws.permeability);
      }
      ++pairs;
    }
  }
  EXPECT_EQ(pairs, static_cast<int>(std::variant_size_v<AnySolidLaw> *
                                    std::variant_size_v<AnyPermeabilityLaw>));
}

TEST(MaterialLawRegistry, DefaultsAreTheFirstRegisteredLaws) {
  const MaterialConfig m;
  EXPECT_EQ(m.solid_law, "neo_hookean");
  EXPECT_EQ(m.permeability_law, "constant");
  const MaterialLaws laws = make_material_laws(m);
  EXPECT_TRUE(std::holds_alternative<NeoHookean>(laws.solid));
  EXPECT_TRUE(std::holds_alternative<ConstantPermeability>(laws.permeability));
  EXPECT_EQ(laws.reference_permeability(), 1e-3);  // the declared default of k0
}

TEST(MaterialLawRegistry, UnknownParametersAndLawsAreRefused) {
  MaterialConfig m;
  EXPECT_THROW(m.set("lamda", 0.3), std::invalid_argument);
  EXPECT_THROW((void)m.get("lamda"), std::invalid_argument);
  m.set("lambda", 0.3);
  EXPECT_EQ(m.get("lambda"), 0.3);
  m.permeability_law = "darcy";
  EXPECT_THROW((void)make_material_laws(m), std::invalid_argument);
}

}  // namespace
}  // namespace biphasic
