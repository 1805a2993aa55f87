#include "fem/gmsh/msh_cursor.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace bipot::msh {

namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// A word as a message shows it: at most 24 characters, bytes that are not printable ASCII
/// as '?' (the file may be binary or hostile).
std::string shown(std::string_view w) {
  if (w.empty()) return "the end of the file";
  std::string s = "'";
  for (std::size_t i = 0; i < std::min<std::size_t>(w.size(), 24); ++i)
    s += (w[i] >= 0x20 && w[i] < 0x7f) ? w[i] : '?';
  return s + (w.size() > 24 ? "...'" : "'");
}

} // namespace

void Cursor::fail_at(std::size_t at, const std::string& message) const {
  at = std::min(at, text_.size());
  const auto line = 1 + std::count(text_.begin(), text_.begin() + std::ptrdiff_t(at), '\n');
  throw InputError(path_ + ":" + std::to_string(line) + ": " + message);
}

void Cursor::skip_space() {
  while (pos_ < text_.size() && is_space(text_[pos_]))
    ++pos_;
}

std::size_t Cursor::mark() {
  if (!binary_) skip_space();
  return pos_;
}

bool Cursor::at_end() {
  skip_space();
  return pos_ == text_.size();
}

std::string_view Cursor::word() {
  skip_space();
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]))
    ++pos_;
  return text_.substr(start, pos_ - start);
}

void Cursor::expect(std::string_view expected, const std::string& context) {
  const std::size_t before = mark();
  const std::string_view w = word();
  if (w != expected)
    fail_at(before, context + ": expected " + std::string(expected) + ", found " + shown(w));
}

std::string_view Cursor::line() {
  const std::size_t start = pos_;
  const std::size_t end = text_.find('\n', pos_);
  pos_ = end == std::string_view::npos ? text_.size() : end + 1;
  std::string_view l = text_.substr(start, (end == std::string_view::npos ? pos_ : end) - start);
  if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
  return l;
}

bool Cursor::skip_past_line(std::string_view marker) {
  while (pos_ < text_.size()) {
    std::string_view l = line();
    while (!l.empty() && is_space(l.back()))
      l.remove_suffix(1);
    while (!l.empty() && is_space(l.front()))
      l.remove_prefix(1);
    if (l == marker) return true;
  }
  return false;
}

const unsigned char* Cursor::take(std::size_t bytes, const std::string& what) {
  if (remaining() < bytes) fail(what + ": the file ends inside the binary data");
  const auto* p = reinterpret_cast<const unsigned char*>(text_.data() + pos_);
  pos_ += bytes;
  return p;
}

template <class Stored, class T>
T Cursor::field(const std::string& what, const char* kind, std::size_t before) {
  T v{};
  if (binary_) {
    Stored b{};
    std::memcpy(&b, take(sizeof b, what), sizeof b);
    v = static_cast<T>(b);
    return v;
  }
  const std::string_view w = word();
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
  // A real number out of range (1e999) is not refused here: real() decides.
  const bool range = std::is_floating_point_v<T> && ec == std::errc::result_out_of_range;
  if (w.empty() || end != w.data() + w.size() || (ec != std::errc() && !range))
    fail_at(before, what + ": expected " + kind + ", found " + shown(w));
  if (range) v = std::numeric_limits<T>::infinity();
  return v;
}

template <class T>
void Cursor::check_range(const std::string& what, T v, T lo, T hi, std::size_t before) const {
  if (v < lo || v > hi)
    fail_at(before, what + " is " + std::to_string(v) + ", outside [" + std::to_string(lo) + ", " +
                        std::to_string(hi) + "]");
}

long long Cursor::integer(const std::string& what, long long lo, long long hi) {
  const std::size_t before = mark();
  const auto v = field<std::int32_t, long long>(what, "an integer", before);
  check_range(what, v, lo, hi, before);
  return v;
}

std::uint64_t Cursor::count(const std::string& what, std::uint64_t lo, std::uint64_t hi) {
  const std::size_t before = mark();
  const auto v = field<std::uint64_t, std::uint64_t>(what, "a non-negative integer", before);
  check_range(what, v, lo, hi, before);
  return v;
}

double Cursor::real(const std::string& what, bool finite) {
  const std::size_t before = mark();
  const double v = field<double, double>(what, "a number", before);
  if (finite && !std::isfinite(v)) fail_at(before, what + " is not a finite number");
  return v;
}

std::uint64_t Cursor::capacity(std::size_t min_words, std::size_t min_bytes) const {
  // An ASCII word takes at least two bytes: one character and a separator.
  // (The last word of the file needs no separator, hence the + 1.)
  if (binary_) return min_bytes == 0 ? remaining() : remaining() / min_bytes;
  return min_words == 0 ? remaining() : (remaining() + 1) / (2 * min_words);
}

} // namespace bipot::msh
