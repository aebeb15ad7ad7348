#include "biphasic/study/measures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "biphasic/io/line_probe.hpp"
#include "biphasic/time/semidiscrete_system.hpp"

namespace biphasic {

std::string to_string(DrainedEnds ends) {
  switch (ends) {
    case DrainedEnds::Start:
      return "start";
    case DrainedEnds::End:
      return "end";
    case DrainedEnds::Both:
      return "both";
    case DrainedEnds::None:
      break;
  }
  return "none";
}

int allowed_turning_points(DrainedEnds ends) {
  return ends == DrainedEnds::Start || ends == DrainedEnds::End ? 0 : 1;
}

double excess_variation(const std::vector<double>& p, int turning_points) {
  if (turning_points != 0 && turning_points != 1)
    throw std::invalid_argument("excess_variation: turning_points must be 0 or 1, not " +
                                std::to_string(turning_points));
  if (p.empty()) return 0.0;
  double variation = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i) variation += std::abs(p[i] - p[i - 1]);
  const double first = p.front(), last = p.back();
  double needed = std::abs(last - first);
  if (turning_points == 1)
    for (double pk : p) needed = std::max(needed, std::abs(pk - first) + std::abs(last - pk));
  return std::max(0.0, variation - needed);
}

LineMeasures line_measures(const std::vector<double>& s, const std::vector<double>& p,
                           DrainedEnds drained) {
  if (s.size() != p.size() || s.size() < 2)
    throw std::invalid_argument("line_measures: need at least two (s, p) pairs of equal count");
  LineMeasures m;
  m.p_mid = interpolate_on_line(s, p, 0.5 * (s.front() + s.back()));
  const auto [lo, hi] = std::minmax_element(p.begin(), p.end());
  m.p_min = *lo;
  m.p_max = *hi;
  m.defined = m.p_mid != 0.0;
  if (m.defined) {
    m.overshoot = (m.p_max - m.p_mid) / m.p_mid;
    m.undershoot = -m.p_min / m.p_mid + 0.0;  // + 0.0: no "-0" when min p = 0
    m.oscillation =
        excess_variation(p, allowed_turning_points(drained)) / (2.0 * std::abs(m.p_mid));
  }
  return m;
}

DrainedEnds drained_ends(const LineProbe& probe, const SemidiscreteSystem& problem) {
  return drained_ends(probe, problem.constrained(), problem.pattern().p_dof(0));
}

DrainedEnds drained_ends(const LineProbe& probe, const std::vector<char>& constrained,
                         Index first_pressure) {
  // Weights below this are round-off (a point on an element face has the opposite vertex's
  // weight ~1e-16, not 0).
  constexpr double kNegligible = 1e-9;
  auto drained = [&](std::size_t i) {
    for (const auto& [vertex, weight] : probe.sample(i).p_weights) {
      if (std::abs(weight) > kNegligible &&
          !constrained[static_cast<std::size_t>(first_pressure + vertex)])
        return false;
    }
    return true;
  };
  const bool start = drained(0), end = drained(probe.size() - 1);
  if (start && end) return DrainedEnds::Both;
  if (start) return DrainedEnds::Start;
  return end ? DrainedEnds::End : DrainedEnds::None;
}

}  // namespace biphasic
