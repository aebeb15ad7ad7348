#include "biphasic/study/measures.hpp"

#include <algorithm>
#include <stdexcept>

#include "biphasic/io/line_probe.hpp"

namespace biphasic {

LineMeasures line_measures(const std::vector<double>& s, const std::vector<double>& p) {
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
  }
  return m;
}

}  // namespace biphasic
