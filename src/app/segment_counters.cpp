#include "biphasic/app/segment_counters.hpp"

#include <algorithm>
#include <string>

namespace biphasic {

namespace {

/// Counters whose total over segments is their largest value, not their sum.
bool is_maximum(const std::string& key) { return key == "max_krylov_iterations" || key == "max"; }
/// Values that describe the latest state, not work done: the segment's value stands.
bool is_state(const std::string& key) {
  return key == "fill_ratio" || key == "absolute_tolerances" || key == "median";
}

nlohmann::json combine(const std::string& key, const nlohmann::json& a, const nlohmann::json& b) {
  if (is_state(key)) return b;
  if (key == "min" && a.is_number() && b.is_number())
    return std::min(a.get<double>(), b.get<double>());
  if (is_maximum(key) && a.is_number() && b.is_number()) {
    if (a.is_number_integer() && b.is_number_integer())
      return std::max(a.get<long long>(), b.get<long long>());
    return std::max(a.get<double>(), b.get<double>());
  }
  if (a.is_number_integer() && b.is_number_integer())
    return a.get<long long>() + b.get<long long>();
  if (a.is_number() && b.is_number()) return a.get<double>() + b.get<double>();
  if (a.is_object() && b.is_object()) return combine_segments(a, b);
  if (a.is_array() && b.is_array()) {
    const bool numbers =
        std::all_of(a.begin(), a.end(), [](const auto& v) { return v.is_number(); }) &&
        std::all_of(b.begin(), b.end(), [](const auto& v) { return v.is_number(); });
    if (numbers && a.size() == b.size() && !a.empty()) {  // per-order counts
      nlohmann::json sum = nlohmann::json::array();
      for (std::size_t i = 0; i < a.size(); ++i) sum.push_back(combine("", a[i], b[i]));
      return sum;
    }
    nlohmann::json all = a;  // events: consistent starts, cut-backs
    all.insert(all.end(), b.begin(), b.end());
    return all;
  }
  return b;
}

}  // namespace

nlohmann::json combine_segments(const nlohmann::json& earlier, const nlohmann::json& segment) {
  if (earlier.is_null()) return segment;
  if (earlier.is_array() && segment.is_array()) return combine("", earlier, segment);
  if (!earlier.is_object() || !segment.is_object()) return segment;
  nlohmann::json total = earlier;
  for (const auto& [key, value] : segment.items())
    total[key] = earlier.contains(key) ? combine(key, earlier[key], value) : value;
  return total;
}

}  // namespace biphasic
