// The stabilisation registry: each registered stabilisation's per-element coefficients against
// their closed forms (the need-following ones against c_e = max(0, r* h²/k − H_A Δt*) and
// β = max(0, r* h²/H_A − k Δt*)), the case file accepting exactly the registered names, and an
// unknown name refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <variant>

#include "../case/case_test_support.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/physics/element_stabilisation.hpp"
#include "biphasic/physics/stabilisation/stabilisations.hpp"

namespace biphasic {
namespace {

MaterialLaws paper_material() {
  return make_material_laws(MaterialConfig::neo_hookean(0.2, 0.5, 2e-3));
}

TEST(Stabilisations, CoefficientsFollowTheirClosedForms) {
  const MaterialLaws laws = paper_material();
  const double h2 = 0.36;  // scale · h² [mm²]
  const ElementCoefficients none = element_coefficients(make_stabilisation("none"), h2, laws, {});
  EXPECT_EQ(none.gls_c, 0.0);
  EXPECT_EQ(none.flux_beta, 0.0);
  const ElementCoefficients gls = element_coefficients(make_stabilisation("gls"), h2, laws, {});
  EXPECT_DOUBLE_EQ(gls.gls_c, 0.36 / (4.0 * 2e-3));  // c_e = h²/(4 k(1)) [MPa s]
  EXPECT_EQ(gls.flux_beta, 0.0);
  const ElementCoefficients flux =
      element_coefficients(make_stabilisation("flux_perturbation"), h2, laws, {});
  EXPECT_DOUBLE_EQ(flux.flux_beta, 0.36 / (4.0 * 1.2));  // β = h²/(4 H_A), H_A = λ + 2μ
  EXPECT_EQ(flux.gls_c, 0.0);
  EXPECT_EQ(gls.volume_rate_dt, 0.0);  // the volume rate is the integrator's, not theirs
}

TEST(Stabilisations, GlsFollowsTheElementsOwnPermeability) {
  MaterialConfig stiff = MaterialConfig::neo_hookean(0.2, 0.5, 2e-3);
  stiff.permeability_law = "holmes_mow";
  stiff.set("permeability_kappa", 2.0);
  const ElementCoefficients c =
      element_coefficients(make_stabilisation("gls"), 1.0, make_material_laws(stiff), {});
  EXPECT_DOUBLE_EQ(c.gls_c, 1.0 / (4.0 * 2e-3));  // c_e,ref from k(1) = k₀
}

// r = k H_A Δt*/h² below, at and above r*: the least coefficients of the first step.
TEST(Stabilisations, NeedFollowingCoefficientsFollowTheirClosedForms) {
  const MaterialLaws laws = paper_material();  // k = 2e-3, H_A = 1.2: c = k H_A = 2.4e-3
  const double h2 = 0.36, threshold = 0.3;
  for (const double r : {0.01, 0.1, 0.29, 0.31, 0.5}) {
    const StabilisationContext context{threshold, r * h2 / 2.4e-3};  // Δt* of that r
    ElementStabilisation gls, flux;
    gls.resize(1);
    flux.resize(1);
    gls.set(0, element_coefficients(make_stabilisation("gls_minimal"), h2, laws, context), laws);
    flux.set(
        0, element_coefficients(make_stabilisation("flux_perturbation_minimal"), h2, laws, context),
        laws);
    gls.finish();
    flux.finish();
    // c_e = γ h²/(4k) with γ = 4 max(0, r* − r); β = b h²/H_A with b = max(0, r* − r).
    const double excess = std::max(0.0, threshold - r);
    EXPECT_NEAR(gls.gls_coefficient(0), 4.0 * excess * h2 / (4.0 * 2e-3), 1e-12) << "r = " << r;
    EXPECT_NEAR(flux.flux_perturbation(0), excess * h2 / 1.2, 1e-15) << "r = " << r;
    // Where the step needs nothing the term is absent, as without stabilisation.
    EXPECT_EQ(gls.has_gls(), r < threshold) << "r = " << r;
    EXPECT_EQ(flux.has_flux_perturbation(), r < threshold) << "r = " << r;
    EXPECT_FALSE(gls.has_flux_perturbation());
    EXPECT_FALSE(flux.has_gls());
  }
  // With the default r* = 1/4 and Δt* → 0 they are the published coefficients.
  const ElementCoefficients published =
      element_coefficients(make_stabilisation("gls"), h2, laws, {});
  const ElementCoefficients least =
      element_coefficients(make_stabilisation("gls_minimal"), h2, laws, {0.25, 0.0});
  EXPECT_DOUBLE_EQ(least.gls_c, published.gls_c);
  EXPECT_EQ(least.gls_offset, 0.0);
}

// A term is present where some element needs it at J = 1; an element clipped there keeps its
// raw coefficients for the kernel, where a strain-dependent k(J) < k(1) switches it on.
TEST(Stabilisations, ClippedElementsKeepTheirRawCoefficients) {
  const MaterialLaws laws = paper_material();
  const double h2 = 0.36;
  const StabilisationContext context{0.25, 0.1 * h2 / 2.4e-3};  // r = 0.1 at h2 = 0.36
  for (const char* type : {"gls_minimal", "flux_perturbation_minimal"}) {
    ElementStabilisation s;
    s.resize(2);
    // Element 0 (h2 = 0.36) needs the term; element 1 (h2 = 0.036, r = 1) does not.
    s.set(0, element_coefficients(make_stabilisation(type), h2, laws, context), laws);
    s.set(1, element_coefficients(make_stabilisation(type), 0.1 * h2, laws, context), laws);
    s.finish();
    EXPECT_TRUE(s.has_gls() || s.has_flux_perturbation()) << type;
    EXPECT_EQ(s.gls_coefficient(1), 0.0) << type;
    EXPECT_EQ(s.flux_perturbation(1), 0.0) << type;
    const ElementCoefficients raw = s.coefficients(1, 0.0);
    EXPECT_GT(raw.gls_c + raw.flux_beta, 0.0) << type;
    // Alone, the element that needs nothing leaves no term.
    ElementStabilisation alone;
    alone.resize(1);
    alone.set(0, element_coefficients(make_stabilisation(type), 0.1 * h2, laws, context), laws);
    alone.finish();
    EXPECT_FALSE(alone.has_gls() || alone.has_flux_perturbation()) << type;
  }
}

TEST(Stabilisations, TheDefaultIsNone) {
  EXPECT_EQ(StabilisationConfig{}.type, "none");
  EXPECT_TRUE(
      std::holds_alternative<NoStabilisation>(make_stabilisation(StabilisationConfig{}.type)));
  EXPECT_EQ(stabilisation_descriptions().front().name, "none");
}

TEST(Stabilisations, TheCaseFileAcceptsExactlyTheRegisteredNames) {
  const std::string& base = testing_support::kMinimalCase;
  for (const StabilisationDescription& d : stabilisation_descriptions()) {
    const Config c =
        parse_case(base + "[stabilisation]\ntype = \"" + d.name + "\"\n", "cases/x.toml", {}, ".");
    EXPECT_EQ(c.stabilisation.type, d.name);
    EXPECT_EQ(describe(make_stabilisation(c.stabilisation.type)).name, d.name);
  }
  try {
    parse_case(base + "[stabilisation]\ntype = \"supg\"\n", "cases/x.toml", {}, ".");
    ADD_FAILURE() << "an unknown stabilisation was accepted";
  } catch (const CaseError& e) {
    const std::string all = e.what();
    EXPECT_NE(all.find("stabilisation.type"), std::string::npos) << all;
    EXPECT_NE(all.find("flux_perturbation"), std::string::npos) << all;  // lists the choices
  }
  EXPECT_THROW((void)make_stabilisation("supg"), std::invalid_argument);
}

}  // namespace
}  // namespace biphasic
