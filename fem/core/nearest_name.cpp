#include "fem/core/nearest_name.hpp"

#include <algorithm>
#include <numeric>

namespace bipot {

int edit_distance(const std::string& a, const std::string& b) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  std::iota(prev.begin(), prev.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  int best_distance = 0;
  for (const auto& c : candidates) {
    const int d = edit_distance(name, c);
    if (best.empty() || d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  const int allowed = std::max<int>(2, static_cast<int>(std::max(name.size(), best.size())) / 3);
  return (!best.empty() && best_distance <= allowed) ? best : std::string();
}

std::string join_names(const std::vector<std::string>& names, const std::string& sep) {
  std::string out;
  for (const auto& n : names) {
    if (!out.empty()) out += sep;
    out += n;
  }
  return out;
}

std::string unknown_in_mesh(const std::string& kind, const std::string& name,
                            const std::vector<std::string>& known) {
  std::string msg = "no " + kind + " named '" + name + "' in the mesh";
  const auto near = nearest_name(name, known);
  if (!near.empty()) msg += " (did you mean '" + near + "'?)";
  return msg + "; available: " + (known.empty() ? std::string("none") : join_names(known));
}

} // namespace bipot
