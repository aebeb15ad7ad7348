// Fluid-volume balance over a backward-Euler run: the body's volume change
//   ΔV(t) = ∫Ω₀ (J(t) − J(t₀)) dX                                         [mm³]
// against the fluid it exchanged, integrated as backward Euler does (rate at the step's end):
//   ∫Q = Σₙ Δtₙ Q(tₙ₊₁),  Q = drained outflow + prescribed outward flux,  ∫S likewise  [mm³]
// Both constituents being incompressible, ΔV + ∫Q − ∫S = 0 in the continuum. Discretely the
// sum of the mass rows is ∫Ω₀ J̇ dX + Q − S, so the conservative J̇ = (J − Jₙ)/Δt keeps the
// balance to the Newton tolerance while the incremental J F⁻ᵀ:∇₀Δu/Δt leaves O(Δt).
#pragma once

#include <vector>

#include "biphasic/physics/biphasic_model.hpp"

namespace biphasic {

struct VolumeBalanceRecord {
  double volume_change = 0.0;       ///< ΔV = ∫Ω₀ (J − J₀) dX [mm³]
  double outflow_integrated = 0.0;  ///< ∫Q dt, Q the net fluid outflow [mm³]
  double source_integrated = 0.0;   ///< ∫S dt, S = ∫Ω₀ s dX the fluid source [mm³]
  /// |ΔV + ∫Q − ∫S| / |ΔV| [-]; NaN while ΔV = 0.
  double relative_imbalance() const;
};

class VolumeBalance {
 public:
  /// Starts at the initial state y0 (ΔV measured from it).
  VolumeBalance(BiphasicModel& problem, const std::vector<double>& y0);
  /// Adds the backward-Euler step of length dt [s] ending at t with its converged y and
  /// ẏ = (y − yₙ)/Δt. Call before the problem's volume-rate setting changes for the next
  /// step: Q is the problem's own mass residual at (t, y, ẏ).
  void add_step(double t, double dt, const std::vector<double>& y, const std::vector<double>& ydot);
  /// Continues a balance recorded earlier (a restarted run): the next steps add to `record`.
  void resume(const VolumeBalanceRecord& record) { record_ = record; }
  /// The balance after the last step added.
  const VolumeBalanceRecord& record() const { return record_; }

 private:
  BiphasicModel& problem_;
  double initial_ = 0.0;  ///< ∫Ω₀ (J₀ − 1) dX [mm³]
  VolumeBalanceRecord record_;
};

}  // namespace biphasic
