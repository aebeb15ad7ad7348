#include "biphasic/fe/point_locator.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "biphasic/fe/shape_functions.hpp"

namespace biphasic {

namespace {

Vec3 vec(const Point& p) { return {p[0], p[1], p[2]}; }

/// Barycentric coordinates (L₀, …, L₃) of reference coordinates ξ.
std::array<double, 4> barycentric(const std::array<double, 3>& xi) {
  return {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
}

/// Estimated distance [mm] of the point with reference coordinates ξ outside the element,
/// from the barycentric coordinates and the map's Jacobian J = ∂x/∂ξ there: a point with
/// L_i < 0 lies about −L_i / |∇ₓL_i| beyond face i.
double distance_outside(const std::array<double, 3>& xi, const Mat3& J) {
  const std::array<double, 4> L = barycentric(xi);
  const Mat3 inv_t = J.inverse().transpose();
  const Eigen::Matrix<double, 4, 3> dL = p1_gradients();
  double d = 0.0;
  for (int i = 0; i < 4; ++i) {
    if (L[i] >= 0.0) continue;
    const double g = (inv_t * dL.row(i).transpose()).norm();
    d = std::max(d, -L[i] / g);
  }
  return d;
}

}  // namespace

PointLocation locate_in_element(const std::array<Point, 10>& X, const Point& x) {
  const Vec3 x0 = vec(X[0]);
  Mat3 J0;
  for (int j = 0; j < 3; ++j) J0.col(j) = vec(X[j + 1]) - x0;
  const Vec3 xi0 = J0.partialPivLu().solve(vec(x) - x0);

  PointLocation loc;
  loc.xi = {xi0(0), xi0(1), xi0(2)};
  Mat3 J = J0;

  // Curved when an edge node is off its edge's midpoint by more than round-off.
  double size = 0.0, offset = 0.0;
  for (std::size_t e = 0; e < kTetEdges.size(); ++e) {
    const Vec3 a = vec(X[kTetEdges[e][0]]), b = vec(X[kTetEdges[e][1]]);
    size = std::max(size, (b - a).norm());
    offset = std::max(offset, (vec(X[4 + e]) - 0.5 * (a + b)).norm());
  }
  const std::array<double, 4> L0 = barycentric(loc.xi);
  const bool curved = offset > 1e-12 * size;
  // A point far outside the straight element is outside the curved one too (its edges bow by
  // a fraction of their length); Newton's method need not converge there.
  if (curved && *std::min_element(L0.begin(), L0.end()) > -0.5) {
    Eigen::Matrix<double, 10, 3> Xm;
    for (int a = 0; a < 10; ++a) Xm.row(a) = vec(X[a]).transpose();
    std::array<double, 3> xi = loc.xi;
    bool converged = false;
    for (int iteration = 0; iteration < 30 && !converged; ++iteration) {
      const Vec3 r = Xm.transpose() * p2_values(xi) - vec(x);
      const Mat3 Jk = Xm.transpose() * p2_gradients(xi);
      if (!(std::abs(Jk.determinant()) > 0.0)) break;
      const Vec3 step = Jk.partialPivLu().solve(r);
      for (int j = 0; j < 3; ++j) xi[j] -= step(j);
      converged = step.lpNorm<Eigen::Infinity>() <=
                  1e-14 * (1.0 + Eigen::Map<Vec3>(xi.data()).lpNorm<Eigen::Infinity>());
      J = Jk;
    }
    if (converged) {
      loc.xi = xi;
      J = Xm.transpose() * p2_gradients(xi);
    } else {
      J = J0;  // keep the straight-sided estimate
    }
  }
  loc.distance_outside = distance_outside(loc.xi, J);
  return loc;
}

PointLocator::PointLocator(const Mesh& mesh) : mesh_(mesh) {
  if (mesh.tets.empty() || mesh.nodes.empty())
    throw std::runtime_error("PointLocator: the mesh has no elements");
  lo_.fill(std::numeric_limits<double>::infinity());
  hi_.fill(-std::numeric_limits<double>::infinity());
  for (const Point& p : mesh.nodes) {
    for (int d = 0; d < 3; ++d) {
      lo_[d] = std::min(lo_[d], p[d]);
      hi_[d] = std::max(hi_[d], p[d]);
    }
  }
  // About one element per cell: cell edge h with (box volume) / h³ ≈ number of elements.
  const double n = static_cast<double>(mesh.tets.size());
  double volume = 1.0;
  int flat = 0;
  for (int d = 0; d < 3; ++d) {
    if (hi_[d] > lo_[d])
      volume *= hi_[d] - lo_[d];
    else
      ++flat;
  }
  const double h = flat == 3 ? 1.0 : std::pow(volume / n, 1.0 / (3 - flat));
  for (int d = 0; d < 3; ++d) {
    const double extent = hi_[d] - lo_[d];
    cells_[d] = std::clamp(static_cast<int>(std::ceil(extent / h)), 1, 256);
    cell_size_[d] = extent > 0.0 ? extent / cells_[d] : 1.0;
  }

  // Two passes (count, then fill) over the cells each element's enlarged box meets.
  const std::size_t total = static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
  auto for_each_cell = [&](Index t, auto&& visit) {
    Point blo, bhi;
    blo.fill(std::numeric_limits<double>::infinity());
    bhi.fill(-std::numeric_limits<double>::infinity());
    for (Index node : mesh.tets[static_cast<std::size_t>(t)]) {
      const Point& p = mesh.nodes[static_cast<std::size_t>(node)];
      for (int d = 0; d < 3; ++d) {
        blo[d] = std::min(blo[d], p[d]);
        bhi[d] = std::max(bhi[d], p[d]);
      }
    }
    // Margin for curved elements, which may bow slightly beyond their nodes' box.
    double margin = 0.0;
    for (int d = 0; d < 3; ++d) margin = std::max(margin, bhi[d] - blo[d]);
    margin *= 0.05;
    for (int d = 0; d < 3; ++d) {
      blo[d] -= margin;
      bhi[d] += margin;
    }
    const std::array<int, 3> c0 = cell_of(blo), c1 = cell_of(bhi);
    for (int i = c0[0]; i <= c1[0]; ++i)
      for (int j = c0[1]; j <= c1[1]; ++j)
        for (int k = c0[2]; k <= c1[2]; ++k)
          visit((static_cast<std::size_t>(k) * cells_[1] + j) * cells_[0] + i);
  };
  cell_start_.assign(total + 1, 0);
  const auto num_tets = static_cast<Index>(mesh.tets.size());
  for (Index t = 0; t < num_tets; ++t)
    for_each_cell(t, [&](std::size_t c) { ++cell_start_[c + 1]; });
  for (std::size_t c = 0; c < total; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_tets_.resize(cell_start_[total]);
  std::vector<std::size_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (Index t = 0; t < num_tets; ++t)
    for_each_cell(t, [&](std::size_t c) { cell_tets_[fill[c]++] = t; });
}

std::array<int, 3> PointLocator::cell_of(const Point& x) const {
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d) {
    const double f = std::floor((x[d] - lo_[d]) / cell_size_[d]);
    c[d] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(cells_[d] - 1)));
  }
  return c;
}

double PointLocator::diagonal() const {
  return std::hypot(hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]);
}

std::optional<PointLocation> PointLocator::locate(const Point& x, double tolerance) const {
  for (int d = 0; d < 3; ++d) {
    if (!std::isfinite(x[d]) || x[d] < lo_[d] - tolerance || x[d] > hi_[d] + tolerance)
      return std::nullopt;
  }
  // Every element within the tolerance of x meets one of the cells of the box x ± tolerance.
  const Point blo{x[0] - tolerance, x[1] - tolerance, x[2] - tolerance};
  const Point bhi{x[0] + tolerance, x[1] + tolerance, x[2] + tolerance};
  const std::array<int, 3> c0 = cell_of(blo), c1 = cell_of(bhi);
  std::optional<PointLocation> best;
  for (int i = c0[0]; i <= c1[0]; ++i) {
    for (int j = c0[1]; j <= c1[1]; ++j) {
      for (int k = c0[2]; k <= c1[2]; ++k) {
        const std::size_t c = (static_cast<std::size_t>(k) * cells_[1] + j) * cells_[0] + i;
        for (std::size_t m = cell_start_[c]; m < cell_start_[c + 1]; ++m) {
          const Index t = cell_tets_[m];
          if (best && best->tet == t) continue;
          std::array<Point, 10> X;
          const Tet10& tet = mesh_.tets[static_cast<std::size_t>(t)];
          for (int a = 0; a < 10; ++a) X[a] = mesh_.nodes[static_cast<std::size_t>(tet[a])];
          PointLocation loc = locate_in_element(X, x);
          loc.tet = t;
          if (!best || loc.distance_outside < best->distance_outside ||
              (loc.distance_outside == best->distance_outside && t < best->tet))
            best = loc;
        }
      }
    }
  }
  if (!best || !(best->distance_outside <= tolerance)) return std::nullopt;
  // Onto the element: negative barycentric coordinates (round-off, or a point within the
  // tolerance outside) set to zero, the others rescaled to sum to 1.
  std::array<double, 4> L = barycentric(best->xi);
  if (*std::min_element(L.begin(), L.end()) < 0.0) {
    double sum = 0.0;
    for (double& l : L) {
      l = std::max(l, 0.0);
      sum += l;
    }
    for (double& l : L) l /= sum;
    best->xi = {L[1], L[2], L[3]};
  }
  return best;
}

}  // namespace biphasic
