// Rigid modes left free by the displacement conditions: for each connected part, the fixed
// components are the rows of A (n × 6), A_k = r_k(X)·e_c for the modes r_k = e_x, e_y, e_z
// (translations) and e_j × (X − c) / L (rotations about the centroid c, scaled by the part's
// size L so that every entry is at most 1). A is reduced row by row to its 6 × 6 triangular
// factor R (Givens rotations: AᵀA = RᵀR without forming AᵀA); the right singular vectors of R
// with singular value below 1e-6 span the free motions.
#include "biphasic/mesh/constraint_analysis.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace biphasic {

namespace {

using Vec3 = Eigen::Vector3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Row6 = Eigen::Matrix<double, 6, 1>;

constexpr double kHeld = 1e-6;  // smallest singular value of a held mode (scaled units)

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// Adds the row `r` to the triangular factor `R` (RᵀR += r rᵀ) by Givens rotations.
void add_row(Mat6& R, Row6 r) {
  for (int k = 0; k < 6; ++k) {
    if (r(k) == 0.0) continue;
    const double h = std::hypot(R(k, k), r(k));
    const double c = R(k, k) / h, s = r(k) / h;
    for (int j = k; j < 6; ++j) {
      const double a = R(k, j), b = r(j);
      R(k, j) = c * a + s * b;
      r(j) = -s * a + c * b;
    }
  }
}

/// Orthonormal basis (columns) of the span of `M`'s columns, from its SVD.
Eigen::MatrixXd span_of(const Eigen::MatrixXd& M) {
  if (M.cols() == 0) return Eigen::MatrixXd(M.rows(), 0);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullU);
  int rank = 0;
  for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i)
    if (svd.singularValues()(i) > kHeld) ++rank;
  return svd.matrixU().leftCols(rank);
}

/// The coordinate axes in the span of the orthonormal columns of B, then an orthonormal basis
/// of the rest of that span.
std::pair<std::vector<int>, Eigen::MatrixXd> axes_first(const Eigen::MatrixXd& B) {
  std::vector<int> axes;
  Eigen::MatrixXd named(3, 0);
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = Vec3::Unit(i);
    if ((e - B * (B.transpose() * e)).norm() < 1e-6) {
      axes.push_back(i);
      named.conservativeResize(3, named.cols() + 1);
      named.col(named.cols() - 1) = e;
    }
  }
  // The part of B's span orthogonal to the named axes.
  const Eigen::MatrixXd rest = B - named * (named.transpose() * B);
  return {axes, span_of(rest)};
}

std::string vector_text(const Vec3& v) {
  std::ostringstream s;
  s.precision(4);
  auto clean = [](double x) { return std::abs(x) < 1e-12 ? 0.0 : x; };
  s << "(" << clean(v(0)) << ", " << clean(v(1)) << ", " << clean(v(2)) << ")";
  return s.str();
}

const char* axis_name(int i) { return i == 0 ? "x" : i == 1 ? "y" : "z"; }

/// Describes the free motions spanned by the columns of `null` (scaled coordinates: rows 0–2
/// translation [mm], rows 3–5 rotation × L) of a part with centroid c and size L.
std::vector<FreeMode> describe(const Eigen::MatrixXd& null, const Vec3& c, double L) {
  std::vector<FreeMode> out;
  const Eigen::MatrixXd T = null.topRows(3), W = null.bottomRows(3);
  // Pure translations: combinations of the null vectors without rotation.
  Eigen::MatrixXd no_rotation(null.cols(), 0);
  {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(W, Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();
    int rank = 0;
    for (Eigen::Index i = 0; i < sv.size(); ++i)
      if (sv(i) > kHeld) ++rank;
    no_rotation = svd.matrixV().rightCols(null.cols() - rank);
  }
  const Eigen::MatrixXd translations = span_of(T * no_rotation);
  const auto [t_axes, t_rest] = axes_first(translations);
  for (int i : t_axes) out.push_back({std::string("translation ") + axis_name(i), true, i});
  for (Eigen::Index k = 0; k < t_rest.cols(); ++k)
    out.push_back({"translation along " + vector_text(t_rest.col(k)), true, -1});

  // Rotations: the rotation directions present, each with its axis point.
  const Eigen::MatrixXd directions = span_of(W);
  const auto [r_axes, r_rest] = axes_first(directions);
  std::vector<std::pair<Vec3, int>> rotations;
  for (int i : r_axes) rotations.emplace_back(Vec3::Unit(i), i);
  for (Eigen::Index k = 0; k < r_rest.cols(); ++k) rotations.emplace_back(r_rest.col(k), -1);
  const Eigen::MatrixXd W_pinv =
      W.completeOrthogonalDecomposition().pseudoInverse();  // null.cols() × 3
  for (const auto& [w, axis] : rotations) {
    const Eigen::VectorXd a = W_pinv * w;
    Vec3 t = T * a;
    if (translations.cols() > 0) t -= translations * (translations.transpose() * t);
    // u(X) = t + (w / L) × (X − c): the axis passes through p = c + L (w × t); a slide
    // along it of L (w · t) per radian makes it a screw.
    const Vec3 p = c + L * w.cross(t);
    const double slide = L * w.dot(t);
    // With every translation across w free too, the axis may pass anywhere.
    const Vec3 across = w.unitOrthogonal(), across2 = w.cross(across);
    const auto free_translation = [&](const Vec3& u) {
      return translations.cols() > 0 &&
             (u - translations * (translations.transpose() * u)).norm() < 1e-6;
    };
    std::ostringstream s;
    s << "rotation about " << (axis >= 0 ? axis_name(axis) : "the axis " + vector_text(w));
    if (!free_translation(across) || !free_translation(across2))
      s << " through " << vector_text(p) << " mm";
    if (std::abs(slide) > 1e-6 * L) s << " with a slide of " << slide << " mm per radian";
    out.push_back({s.str(), false, axis});
  }
  return out;
}

}  // namespace

MeshParts connected_parts(const Mesh& mesh) {
  const Index nn = mesh.num_nodes();
  std::vector<int> parent(static_cast<std::size_t>(nn));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> used(static_cast<std::size_t>(nn), 0);
  for (const Tet10& t : mesh.tets) {
    const int r0 = find_root(parent, static_cast<int>(t[0]));
    used[t[0]] = 1;
    for (int a = 1; a < 10; ++a) {
      used[t[a]] = 1;
      const int r = find_root(parent, static_cast<int>(t[a]));
      if (r != r0) parent[r] = find_root(parent, r0);
    }
  }
  MeshParts parts;
  parts.part_of_node.assign(static_cast<std::size_t>(nn), -1);
  std::vector<int> part_of_root(static_cast<std::size_t>(nn), -1);
  for (const Tet10& t : mesh.tets) {
    int& p = part_of_root[find_root(parent, static_cast<int>(t[0]))];
    if (p < 0) {
      p = parts.count++;
      parts.tets.push_back(0);
    }
    ++parts.tets[p];
  }
  for (Index n = 0; n < nn; ++n)
    if (used[n]) parts.part_of_node[n] = part_of_root[find_root(parent, static_cast<int>(n))];
  return parts;
}

std::vector<PartFreedom> free_rigid_modes(const Mesh& mesh,
                                          const std::vector<FixedComponent>& fixed) {
  const MeshParts parts = connected_parts(mesh);
  std::vector<PartFreedom> out(static_cast<std::size_t>(parts.count));
  std::vector<Vec3> centroid(out.size(), Vec3::Zero());
  std::vector<Index> nodes(out.size(), 0);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const int p = parts.part_of_node[n];
    if (p < 0) continue;
    centroid[p] += Vec3(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]);
    ++nodes[p];
  }
  std::vector<double> size(out.size(), 0.0);
  for (std::size_t p = 0; p < out.size(); ++p) centroid[p] /= static_cast<double>(nodes[p]);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const int p = parts.part_of_node[n];
    if (p < 0) continue;
    const Vec3 X(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]);
    size[p] = std::max(size[p], (X - centroid[p]).norm());
  }

  std::vector<Mat6> R(out.size(), Mat6::Zero());
  for (const FixedComponent& f : fixed) {
    if (f.node < 0 || f.node >= mesh.num_nodes() || f.component < 0 || f.component > 2)
      throw std::out_of_range("free_rigid_modes: node " + std::to_string(f.node) + " component " +
                              std::to_string(f.component) + " out of range");
    const int p = parts.part_of_node[f.node];
    if (p < 0) continue;
    const Vec3 X(mesh.nodes[f.node][0], mesh.nodes[f.node][1], mesh.nodes[f.node][2]);
    const Vec3 d = (X - centroid[p]) / std::max(size[p], 1e-300);
    Row6 row = Row6::Zero();
    row(f.component) = 1.0;
    for (int j = 0; j < 3; ++j) row(3 + j) = Vec3::Unit(j).cross(d)(f.component);
    add_row(R[p], row);
    ++out[p].fixed;
  }

  for (std::size_t p = 0; p < out.size(); ++p) {
    PartFreedom& part = out[p];
    part.part = static_cast<int>(p);
    part.tets = parts.tets[p];
    part.centroid = {centroid[p](0), centroid[p](1), centroid[p](2)};
    part.size = size[p];
    Eigen::JacobiSVD<Mat6> svd(R[p], Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();  // decreasing
    int rank = 0;
    for (int i = 0; i < 6; ++i)
      if (sv(i) > kHeld) ++rank;
    if (rank == 6) continue;
    part.free = describe(svd.matrixV().rightCols(6 - rank), centroid[p], size[p]);
  }
  return out;
}

}  // namespace biphasic
