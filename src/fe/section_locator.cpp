#include "biphasic/fe/section_locator.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

namespace {

/// Barycentric coordinates (1 − η₁ − η₂, η₁, η₂).
std::array<double, 3> barycentric(const std::array<double, 2>& eta) {
  return {1.0 - eta[0] - eta[1], eta[0], eta[1]};
}

}  // namespace

SectionPointLocation locate_in_triangle(const std::array<Point2, 6>& X, const Point2& x) {
  Eigen::Matrix<double, 2, 6> Xm;
  for (int a = 0; a < 6; ++a) Xm.col(a) = Eigen::Vector2d(X[a][0], X[a][1]);
  // Straight-sided guess from the corners.
  Eigen::Matrix2d A;
  A.col(0) = Xm.col(1) - Xm.col(0);
  A.col(1) = Xm.col(2) - Xm.col(0);
  const Eigen::Vector2d r = Eigen::Vector2d(x[0], x[1]) - Xm.col(0);
  Eigen::Vector2d eta = A.partialPivLu().solve(r);
  // Edge nodes off their midpoints: the map is curved, invert it by Newton.
  double size = std::max(A.col(0).norm(), A.col(1).norm());
  double bend = 0.0;
  for (std::size_t k = 0; k < kTriEdges.size(); ++k) {
    const Eigen::Vector2d mid = 0.5 * (Xm.col(kTriEdges[k][0]) + Xm.col(kTriEdges[k][1]));
    bend = std::max(bend, (Xm.col(3 + static_cast<Eigen::Index>(k)) - mid).norm());
  }
  Eigen::Matrix2d jac = A;
  if (bend > 1e-12 * size) {
    for (int it = 0; it < 30; ++it) {
      const std::array<double, 2> e{eta(0), eta(1)};
      const Eigen::Vector2d residual = Xm * tri6_values(e) - Eigen::Vector2d(x[0], x[1]);
      jac = Xm * tri6_gradients(e);
      const Eigen::Vector2d step = jac.partialPivLu().solve(residual);
      eta -= step;
      if (!std::isfinite(eta(0)) || !std::isfinite(eta(1))) break;
      if (step.norm() < 1e-14) break;
    }
    jac = Xm * tri6_gradients({eta(0), eta(1)});
  }
  SectionPointLocation loc;
  loc.eta = {eta(0), eta(1)};
  // ∇ₓL_i = J⁻ᵀ ∇_η L_i with ∇_η L = (−1, −1), (1, 0), (0, 1).
  const Eigen::Matrix2d jinvT = jac.inverse().transpose();
  const std::array<Eigen::Vector2d, 3> dL{Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d(1.0, 0.0),
                                          Eigen::Vector2d(0.0, 1.0)};
  const std::array<double, 3> L = barycentric(loc.eta);
  for (int i = 0; i < 3; ++i) {
    if (L[i] < 0.0) {
      loc.distance_outside = std::max(loc.distance_outside, -L[i] / (jinvT * dL[i]).norm());
    }
  }
  if (!std::isfinite(eta(0)) || !std::isfinite(eta(1)))
    loc.distance_outside = std::numeric_limits<double>::infinity();
  return loc;
}

SectionPointLocator::SectionPointLocator(const SectionMesh& mesh) : mesh_(mesh) {
  if (mesh.triangles.empty())
    throw std::runtime_error("SectionPointLocator: mesh has no triangles");
  constexpr double inf = std::numeric_limits<double>::infinity();
  lo_ = {inf, inf};
  hi_ = {-inf, -inf};
  boxes_.reserve(mesh.triangles.size());
  for (const Tri6& tri : mesh.triangles) {
    std::array<double, 4> box{inf, inf, -inf, -inf};
    for (Index n : tri) {
      const Point2& x = mesh.nodes[static_cast<std::size_t>(n)];
      for (int d = 0; d < 2; ++d) {
        box[d] = std::min(box[d], x[d]);
        box[2 + d] = std::max(box[2 + d], x[d]);
      }
    }
    for (int d = 0; d < 2; ++d) {
      lo_[d] = std::min(lo_[d], box[d]);
      hi_[d] = std::max(hi_[d], box[2 + d]);
    }
    boxes_.push_back(box);
  }
}

double SectionPointLocator::diagonal() const {
  return std::hypot(hi_[0] - lo_[0], hi_[1] - lo_[1]);
}

std::optional<SectionPointLocation> SectionPointLocator::locate(const Point2& x,
                                                                double tolerance) const {
  if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return std::nullopt;
  // A curved edge can bulge past its nodes' box: enlarge the boxes a little beyond the tolerance.
  const double margin = tolerance + 1e-9 * std::max(diagonal(), 1.0);
  std::optional<SectionPointLocation> best;
  for (std::size_t t = 0; t < boxes_.size(); ++t) {
    const auto& box = boxes_[t];
    const double pad = margin + 0.25 * std::max(box[2] - box[0], box[3] - box[1]);
    if (x[0] < box[0] - pad || x[0] > box[2] + pad || x[1] < box[1] - pad || x[1] > box[3] + pad)
      continue;
    std::array<Point2, 6> X;
    const Tri6& tri = mesh_.triangles[t];
    for (int a = 0; a < 6; ++a) X[a] = mesh_.nodes[static_cast<std::size_t>(tri[a])];
    SectionPointLocation loc = locate_in_triangle(X, x);
    loc.triangle = static_cast<Index>(t);
    if (!best || loc.distance_outside < best->distance_outside) best = loc;
    if (best->distance_outside == 0.0) break;  // inside: the first triangle holding x
  }
  if (!best || !(best->distance_outside <= tolerance)) return std::nullopt;
  std::array<double, 3> L = barycentric(best->eta);
  if (*std::min_element(L.begin(), L.end()) < 0.0) {
    double sum = 0.0;
    for (double& l : L) {
      l = std::max(l, 0.0);
      sum += l;
    }
    for (double& l : L) l /= sum;
    best->eta = {L[1], L[2]};
  }
  return best;
}

}  // namespace biphasic
