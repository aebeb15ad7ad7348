#include "biphasic/physics/volume_balance.hpp"

#include <cmath>
#include <limits>

namespace biphasic {

double VolumeBalanceRecord::relative_imbalance() const {
  if (volume_change == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return std::abs(volume_change + outflow_integrated - source_integrated) / std::abs(volume_change);
}

VolumeBalance::VolumeBalance(BiphasicModel& problem, const std::vector<double>& y0)
    : problem_(problem), initial_(problem.volume_change(y0.data())) {}

void VolumeBalance::add_step(double t, double dt, const std::vector<double>& y,
                             const std::vector<double>& ydot) {
  const FluidRates q = problem_.fluid_rates(t, y.data(), ydot.data());
  record_.outflow_integrated += dt * (q.drained + q.prescribed);
  record_.source_integrated += dt * q.source;
  record_.volume_change = problem_.volume_change(y.data()) - initial_;
}

}  // namespace biphasic
