// A manufactured solution of the finite-strain biphasic model on the unit cube (method of
// manufactured solutions: Roache; Salari & Knupp, "Code verification by the method of
// manufactured solutions", Sandia report SAND2000-1444, 2000).
//
// Exact fields, linear in t (zero at t = 0, so y = 0 is an exact, consistent initial state):
//   u(X, t) = t U(X),  U = A (sin(1.1x + 0.7y) cos(0.9z),  cos(0.8x − 0.6z) e^{0.5y},
//                             sin(0.9xy + 1.2z))
//   p(X, t) = t P(X),  P = P₀ cos(1.3x) sin(0.9y + 0.5) e^{0.4z}
// With A = 0.08 mm the displacement gradient reaches about 0.15 at t = 1 (J from about 0.9 to
// 1.1): a genuinely finite deformation. The loads that make them exact, for the model of
// The model of docs/formulation.md written out again here (independently of src/material):
//   b = −Div P,   P = μ(F − F⁻ᵀ) + λ ln J F⁻ᵀ − p J F⁻ᵀ,  F = I + ∇₀u
//   s = J̇ − Div Q, Q = k J C⁻¹ ∇₀p                         (mass balance J̇ + Div W = s, W = −Q)
// The divergences are complex-step derivatives of the closed-form P and Q (exact to rounding:
// no subtractive cancellation), J̇ a complex-step derivative in t.
#pragma once

#include <Eigen/Dense>
#include <complex>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic::mms {

struct Parameters {
  double lambda = 0.2;      ///< [MPa]
  double mu = 0.5;          ///< [MPa]
  double k = 0.1;           ///< permeability [mm⁴ N⁻¹ s⁻¹]
  double amplitude = 0.08;  ///< A [mm/s]
  double pressure = 0.1;    ///< P₀ [MPa/s]
  /// P = P₀ (1 + 0.5x − 0.3y + 0.2z) instead: a pressure P1 holds exactly, so the pressure
  /// error comes from the coupling alone.
  bool linear_pressure = false;
};

template <class T>
using Vec3T = Eigen::Matrix<T, 3, 1>;
template <class T>
using Mat3T = Eigen::Matrix<T, 3, 3>;

/// U, ∇₀U (row i: ∇U_i), P and ∇₀P at X, for a real or complex X.
template <class T>
struct Spatial {
  Vec3T<T> U;
  Mat3T<T> gradU;
  T P;
  Vec3T<T> gradP;
};

template <class T>
Spatial<T> spatial(const Vec3T<T>& X, const Parameters& m) {
  using std::cos;
  using std::exp;
  using std::sin;
  const T x = X(0), y = X(1), z = X(2);
  const double A = m.amplitude, P0 = m.pressure;
  Spatial<T> f;
  const T a = 1.1 * x + 0.7 * y, b = 0.8 * x - 0.6 * z, c = 0.9 * x * y + 1.2 * z;
  const T ey = exp(0.5 * y);
  f.U << A * sin(a) * cos(0.9 * z), A * cos(b) * ey, A * sin(c);
  f.gradU << A * 1.1 * cos(a) * cos(0.9 * z), A * 0.7 * cos(a) * cos(0.9 * z),
      -A * 0.9 * sin(a) * sin(0.9 * z),                                      //
      -A * 0.8 * sin(b) * ey, A * 0.5 * cos(b) * ey, A * 0.6 * sin(b) * ey,  //
      A * 0.9 * y * cos(c), A * 0.9 * x * cos(c), A * 1.2 * cos(c);
  if (m.linear_pressure) {
    f.P = P0 * (1.0 + 0.5 * x - 0.3 * y + 0.2 * z);
    f.gradP << T(0.5 * P0), T(-0.3 * P0), T(0.2 * P0);
    return f;
  }
  const T d = 0.9 * y + 0.5, ez = exp(0.4 * z);
  f.P = P0 * cos(1.3 * x) * sin(d) * ez;
  f.gradP << -1.3 * P0 * sin(1.3 * x) * sin(d) * ez, 0.9 * P0 * cos(1.3 * x) * cos(d) * ez,
      0.4 * f.P;
  return f;
}

/// F = I + t ∇₀U.
template <class T>
Mat3T<T> deformation_gradient(const Spatial<T>& f, T t) {
  return Mat3T<T>::Identity() + t * f.gradU;
}

/// Total first Piola–Kirchhoff stress P(X, t) [MPa].
template <class T>
Mat3T<T> total_stress(const Vec3T<T>& X, T t, const Parameters& m) {
  using std::log;
  const Spatial<T> f = spatial(X, m);
  const Mat3T<T> F = deformation_gradient(f, t);
  const T J = F.determinant();
  const Mat3T<T> FinvT = F.inverse().transpose();
  return m.mu * (F - FinvT) + (m.lambda * log(J) - t * f.P * J) * FinvT;
}

/// Q = k J C⁻¹ ∇₀p [mm/s], the reference seepage with the opposite sign.
template <class T>
Vec3T<T> reference_flux(const Vec3T<T>& X, T t, const Parameters& m) {
  const Spatial<T> f = spatial(X, m);
  const Mat3T<T> F = deformation_gradient(f, t);
  const Mat3T<T> Finv = F.inverse();
  return m.k * F.determinant() * (Finv * Finv.transpose()) * (t * f.gradP);
}

class ManufacturedSolution {
 public:
  explicit ManufacturedSolution(Parameters m = {}) : m_(m) {}
  const Parameters& parameters() const { return m_; }

  Vec3 u(const Vec3& X, double t) const { return t * spatial<double>(X, m_).U; }
  double p(const Vec3& X, double t) const { return t * spatial<double>(X, m_).P; }
  Vec3 u_rate(const Vec3& X, double) const { return spatial<double>(X, m_).U; }
  double p_rate(const Vec3& X, double) const { return spatial<double>(X, m_).P; }

  /// b = −Div P [N/mm³].
  Vec3 body_force(const Vec3& X, double t) const {
    Vec3 b = Vec3::Zero();
    for (int J = 0; J < 3; ++J) {
      const Mat3T<C> P = total_stress<C>(shifted(X, J), C(t), m_);
      for (int i = 0; i < 3; ++i) b(i) -= P(i, J).imag() / kStep;
    }
    return b;
  }

  /// s = J̇ − Div Q [1/s].
  double fluid_source(const Vec3& X, double t) const {
    const Spatial<C> f = spatial<C>(X.cast<C>(), m_);
    const double Jdot = deformation_gradient<C>(f, C(t, kStep)).determinant().imag() / kStep;
    double divQ = 0.0;
    for (int J = 0; J < 3; ++J)
      divQ += reference_flux<C>(shifted(X, J), C(t), m_)(J).imag() / kStep;
    return Jdot - divQ;
  }

 private:
  using C = std::complex<double>;
  static constexpr double kStep = 1e-30;  ///< complex step
  static Vec3T<C> shifted(const Vec3& X, int J) {
    Vec3T<C> Z = X.cast<C>();
    Z(J) += C(0.0, kStep);
    return Z;
  }
  Parameters m_;
};

}  // namespace biphasic::mms
