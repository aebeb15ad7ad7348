// Load-curve evaluation (times in s, values dimensionless).
#include "biphasic/io/config.hpp"

#include <algorithm>

namespace biphasic {

namespace {

/// Index i of the segment [t_i, t_{i+1}) containing t, for t_0 <= t < t_last.
std::size_t segment_of(const std::vector<std::pair<double, double>>& points, double t) {
  const auto after = std::upper_bound(points.begin(), points.end(), t,
                                      [](double x, const auto& p) { return x < p.first; });
  return static_cast<std::size_t>(after - points.begin()) - 1;
}

double segment_slope(const std::vector<std::pair<double, double>>& points, std::size_t i) {
  return (points[i + 1].second - points[i].second) / (points[i + 1].first - points[i].first);
}

}  // namespace

// A curve without points is zero everywhere (validated case files always give one or more).
double LoadCurve::value(double t) const {
  if (points.empty()) return 0.0;
  if (t <= points.front().first) return points.front().second;
  if (t >= points.back().first) return points.back().second;
  const std::size_t i = segment_of(points, t);
  const double fraction = (t - points[i].first) / (points[i + 1].first - points[i].first);
  return points[i].second + fraction * (points[i + 1].second - points[i].second);
}

double LoadCurve::slope(double t) const {
  if (points.size() < 2 || t < points.front().first || t >= points.back().first) return 0.0;
  return segment_slope(points, segment_of(points, t));
}

// Times where the slope jumps, counting the constant extension before the first and after
// the last point (so a ramp's start and end are kinks, a flat end point is not).
std::vector<double> LoadCurve::kinks() const {
  std::vector<double> out;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n && n >= 2; ++i) {
    const double left = i == 0 ? 0.0 : segment_slope(points, i - 1);
    const double right = i + 1 == n ? 0.0 : segment_slope(points, i);
    if (left != right) out.push_back(points[i].first);
  }
  return out;
}

}  // namespace biphasic
