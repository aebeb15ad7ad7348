// The stabilisation registry: each registered stabilisation's per-element coefficients against
// their closed forms, the case file accepting exactly the registered names, and an unknown name
// refused.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <variant>

#include "../case/case_test_support.hpp"
#include "biphasic/io/case_file.hpp"
#include "biphasic/physics/stabilisation/stabilisations.hpp"

namespace biphasic {
namespace {

MaterialLaws paper_material() {
  return make_material_laws(MaterialConfig::neo_hookean(0.2, 0.5, 2e-3));
}

TEST(Stabilisations, CoefficientsFollowTheirClosedForms) {
  const MaterialLaws laws = paper_material();
  const double h2 = 0.36;  // scale · h² [mm²]
  const ElementCoefficients none = element_coefficients(make_stabilisation("none"), h2, laws);
  EXPECT_EQ(none.gls_c, 0.0);
  EXPECT_EQ(none.flux_beta, 0.0);
  const ElementCoefficients gls = element_coefficients(make_stabilisation("gls"), h2, laws);
  EXPECT_DOUBLE_EQ(gls.gls_c, 0.36 / (4.0 * 2e-3));  // c_e = h²/(4 k(1)) [MPa s]
  EXPECT_EQ(gls.flux_beta, 0.0);
  const ElementCoefficients flux =
      element_coefficients(make_stabilisation("flux_perturbation"), h2, laws);
  EXPECT_DOUBLE_EQ(flux.flux_beta, 0.36 / (4.0 * 1.2));  // β = h²/(4 H_A), H_A = λ + 2μ
  EXPECT_EQ(flux.gls_c, 0.0);
  EXPECT_EQ(gls.volume_rate_dt, 0.0);  // the volume rate is the integrator's, not theirs
}

TEST(Stabilisations, GlsFollowsTheElementsOwnPermeability) {
  MaterialConfig stiff = MaterialConfig::neo_hookean(0.2, 0.5, 2e-3);
  stiff.permeability_law = "holmes_mow";
  stiff.set("permeability_kappa", 2.0);
  const ElementCoefficients c =
      element_coefficients(make_stabilisation("gls"), 1.0, make_material_laws(stiff));
  EXPECT_DOUBLE_EQ(c.gls_c, 1.0 / (4.0 * 2e-3));  // c_e,ref from k(1) = k₀
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
