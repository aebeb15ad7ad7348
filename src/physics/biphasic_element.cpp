#include "biphasic/physics/biphasic_element.hpp"

namespace biphasic {

void biphasic_element(const std::vector<PointGeometry>& geometry, const ElementParameters& params,
                      const ElementVector& y, const ElementVector& ydot, bool with_jacobian,
                      ElementOutput& out) {
  biphasic_element(geometry, params.material, ConstantPermeability{params.permeability}, params, y,
                   ydot, with_jacobian, out);
}

}  // namespace biphasic
