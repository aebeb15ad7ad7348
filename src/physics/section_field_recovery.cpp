#include "biphasic/physics/section_field_recovery.hpp"

#include <Eigen/Dense>
#include <stdexcept>
#include <string>
#include <variant>

namespace biphasic {

namespace {

/// Measure-weighted means over one triangle's quadrature points.
struct TriangleMeans {
  Mat3 effective_stress = Mat3::Zero();
  double pressure = 0.0;
  double J = 0.0;
  Vec3 flux = Vec3::Zero();
  double permeability = 0.0;
};

template <SolidLaw Solid, PermeabilityLaw Permeability>
TriangleMeans triangle_means(const std::vector<SectionPointGeometry>& geometry, const Solid& solid,
                             const Permeability& permeability, const Eigen::Matrix<double, 2, 6>& u,
                             const Eigen::Vector3d& p) {
  TriangleMeans m;
  double measure = 0.0;
  for (const SectionPointGeometry& g : geometry) {
    Mat3 F = Mat3::Identity();
    F.topLeftCorner<2, 2>() += u * g.dN;
    F(2, 2) += g.inverse_radius * u.row(0).dot(g.N.transpose());
    const double J = checked_jacobian(F);
    const Mat3 Finv = F.inverse();
    const Mat3 P = solid.response(F, J).first_piola(F, Finv.transpose());
    const Eigen::Vector2d grad0 = g.dNp.transpose() * p;
    const Vec3 grad_p = Finv.transpose() * Vec3(grad0(0), grad0(1), 0.0);  // ∇ₓp = F⁻ᵀ∇₀p
    const double k = permeability.permeability(J);
    const double w = g.weight;
    m.effective_stress += (w / J) * P * F.transpose();
    m.pressure += w * g.Np.dot(p);
    m.J += w * J;
    m.flux -= (w * k) * grad_p;
    m.permeability += w * k;
    measure += w;
  }
  m.effective_stress /= measure;
  m.pressure /= measure;
  m.J /= measure;
  m.flux /= measure;
  m.flux(2) = 0.0;  // no gradient out of the section
  m.permeability /= measure;
  return m;
}

void put_symmetric(const Mat3& s, double* out) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[3 * i + j] = 0.5 * (s(i, j) + s(j, i));
}

}  // namespace

CellFields recover_section_cell_fields(const SectionProblem& problem, const double* y) {
  const SectionMesh& mesh = problem.mesh();
  const SparsityPattern& pattern = problem.pattern();
  const std::size_t n = mesh.triangles.size();
  CellFields out;
  out.stress.resize(9 * n);
  out.effective_stress.resize(9 * n);
  out.J.resize(n);
  out.flux.resize(3 * n);
  out.permeability.resize(n);
  // Section meshes are small: one thread.
  for (std::size_t i = 0; i < n; ++i) {
    const Tri6& tri = mesh.triangles[i];
    Eigen::Matrix<double, 2, 6> u;
    for (int a = 0; a < 6; ++a)
      for (int c = 0; c < 2; ++c) u(c, a) = y[pattern.u_dof(tri[a], c)];
    Eigen::Vector3d p;
    for (int c = 0; c < 3; ++c) p(c) = y[pattern.p_dof(tri[c])];
    const auto e = static_cast<Index>(i);
    const MaterialLaws& laws = problem.laws_of(e);
    TriangleMeans m;
    try {
      m = std::visit(
          [&](const auto& solid, const auto& permeability) {
            return triangle_means(problem.point_geometry(e), solid, permeability, u, p);
          },
          laws.solid, laws.permeability);
    } catch (const std::domain_error& err) {
      throw InvertedElement("triangle " + std::to_string(i) + ": " + err.what());
    }
    put_symmetric(m.effective_stress, &out.effective_stress[9 * i]);
    put_symmetric(m.effective_stress - m.pressure * Mat3::Identity(), &out.stress[9 * i]);
    out.J[i] = m.J;
    for (int c = 0; c < 3; ++c) out.flux[3 * i + c] = m.flux(c);
    out.permeability[i] = m.permeability;
  }
  return out;
}

}  // namespace biphasic
