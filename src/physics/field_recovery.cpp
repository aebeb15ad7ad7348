#include "biphasic/physics/field_recovery.hpp"

#include <Eigen/Dense>
#include <exception>
#include <stdexcept>
#include <string>
#include <variant>

#include "biphasic/assembly/threads.hpp"

namespace biphasic {

namespace {

/// Volume-weighted means over one element's quadrature points.
struct ElementMeans {
  Mat3 effective_stress = Mat3::Zero();
  double pressure = 0.0;
  double J = 0.0;
  Vec3 flux = Vec3::Zero();
  double permeability = 0.0;
};

template <SolidLaw Solid, PermeabilityLaw Permeability>
ElementMeans element_means(const std::vector<PointGeometry>& geometry, const Solid& solid,
                           const Permeability& permeability, const Eigen::Matrix<double, 3, 10>& u,
                           const Eigen::Vector4d& p) {
  ElementMeans m;
  double volume = 0.0;
  for (const PointGeometry& g : geometry) {
    const Mat3 F = Mat3::Identity() + u * g.dN;
    const double J = checked_jacobian(F);
    const Mat3 Finv = F.inverse();
    const Mat3 P = solid.response(F, J).first_piola(F, Finv.transpose());
    const Vec3 grad_p = (g.dNp * Finv).transpose() * p;  // ∇ₓp = F⁻ᵀ∇₀p
    const double k = permeability.permeability(J);
    const double w = g.weight;
    m.effective_stress += (w / J) * P * F.transpose();
    m.pressure += w * g.Np.dot(p);
    m.J += w * J;
    m.flux -= (w * k) * grad_p;
    m.permeability += w * k;
    volume += w;
  }
  m.effective_stress /= volume;
  m.pressure /= volume;
  m.J /= volume;
  m.flux /= volume;
  m.permeability /= volume;
  return m;
}

/// The symmetric part of s, row by row.
void put_symmetric(const Mat3& s, double* out) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[3 * i + j] = 0.5 * (s(i, j) + s(j, i));
}

}  // namespace

CellFields recover_cell_fields(const BiphasicProblem& problem, const double* y) {
  const Mesh& mesh = problem.mesh();
  const SparsityPattern& pattern = problem.pattern();
  const auto count = static_cast<std::ptrdiff_t>(mesh.tets.size());
  const auto n = static_cast<std::size_t>(count);
  CellFields out;
  out.stress.resize(9 * n);
  out.effective_stress.resize(9 * n);
  out.J.resize(n);
  out.flux.resize(3 * n);
  out.permeability.resize(n);

  std::exception_ptr failure;  // the first of any thread, rethrown after the parallel region
  static const int threads = worker_threads();
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t e = 0; e < count; ++e) {
    try {
      const auto i = static_cast<std::size_t>(e);
      const Tet10& tet = mesh.tets[i];
      Eigen::Matrix<double, 3, 10> u;
      for (int a = 0; a < 10; ++a)
        for (int c = 0; c < 3; ++c) u(c, a) = y[pattern.u_dof(tet[a], c)];
      Eigen::Vector4d p;
      for (int c = 0; c < 4; ++c) p(c) = y[pattern.p_dof(tet[c])];
      ElementMeans m;
      const MaterialLaws& laws = problem.laws_of(static_cast<Index>(e));
      try {
        m = std::visit(
            [&](const auto& solid, const auto& permeability) {
              return element_means(problem.point_geometry(static_cast<Index>(e)), solid,
                                   permeability, u, p);
            },
            laws.solid, laws.permeability);
      } catch (const std::domain_error& err) {
        throw InvertedElement("element " + std::to_string(e) + ": " + err.what());
      }
      put_symmetric(m.effective_stress, &out.effective_stress[9 * i]);
      put_symmetric(m.effective_stress - m.pressure * Mat3::Identity(), &out.stress[9 * i]);
      out.J[i] = m.J;
      for (int c = 0; c < 3; ++c) out.flux[3 * i + c] = m.flux(c);
      out.permeability[i] = m.permeability;
    } catch (...) {
#pragma omp critical(biphasic_field_recovery_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace biphasic
