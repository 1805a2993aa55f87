#pragma once
/// Internal to fem/input: what the checks that need the mesh share — a bounded list of
/// problems of one kind, connected groups of nodes, and number formatting.

#include "fem/core/types.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

namespace bipot::input {

/// "%.10g": enough digits to tell two values of an input apart, none of printf's padding.
inline std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

/// "(x, y)" or "(x, y, z)" with number().
inline std::string format_point(const std::array<double, 3>& x, int dim) {
  std::string out = "(" + number(x[0]);
  for (int i = 1; i < dim; ++i)
    out += ", " + number(x[i]);
  return out + ")";
}

/// Problems of one kind, each "<where>: message": the first `shown` of them, then one line
/// counting the rest — a mesh with 10,000 inverted cells needs ten examples, not 10,000 lines.
class BoundedReport {
public:
  BoundedReport(std::string where, std::string kind, std::size_t shown = 10)
      : where_(std::move(where)), kind_(std::move(kind)), shown_(shown) {}

  void add(const std::string& message) { add_line(where_ + ": " + message); }
  /// Adds a problem that carries its own location.
  void add_line(const std::string& line) {
    if (lines_.size() < shown_) lines_.push_back(line);
    ++count_;
  }
  std::size_t count() const { return count_; }
  /// Appends the lines kept and, if some were left out, "<where>: ... and N more <kind>".
  void append_to(std::vector<std::string>& out) const {
    out.insert(out.end(), lines_.begin(), lines_.end());
    if (count_ > lines_.size())
      out.push_back(where_ + ": ... and " + std::to_string(count_ - lines_.size()) + " more " +
                    kind_);
  }

private:
  std::string where_, kind_;
  std::size_t shown_, count_ = 0;
  std::vector<std::string> lines_;
};

/// Disjoint sets of node (or cell) ids, with path halving.
class UnionFind {
public:
  explicit UnionFind(Index n) : parent_(static_cast<std::size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), Index(0));
  }
  Index find(Index i) {
    while (parent_[i] != i)
      i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  /// Joins the sets of `a` and `b`; false if they were already one.
  bool join(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[std::max(a, b)] = std::min(a, b);
    return true;
  }

private:
  std::vector<Index> parent_;
};

} // namespace bipot::input
