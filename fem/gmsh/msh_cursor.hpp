#pragma once
/// Reading position in the bytes of a .msh file, with bounded, checked reads of the fields
/// MSH 4.1 is made of (int, size_t, double), as ASCII tokens or little-endian binary values.
/// Every failure is a bipot::InputError `path:line: message` naming where the reader stood.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace bipot::msh {

class Cursor {
public:
  Cursor(std::string path, std::string_view text) : path_(std::move(path)), text_(text) {}

  /// Binary sections read fields as raw little-endian values (MSH 4.1 binary, data size 8).
  void set_binary(bool binary) { binary_ = binary; }
  bool binary() const { return binary_; }

  std::size_t pos() const { return pos_; }
  /// Start of the next field (ASCII: whitespace skipped), where a message about it points.
  std::size_t mark();
  std::size_t remaining() const { return text_.size() - pos_; }
  bool at_end();

  /// The next whitespace-delimited word ("" at the end of the file).
  std::string_view word();
  /// The next word, which must be `expected` (a section marker such as "$EndNodes").
  void expect(std::string_view expected, const std::string& context);
  /// Rest of the current line (without the line break); moves past it.
  std::string_view line();
  /// Skips to just after the next line that is exactly `marker`; false if there is none.
  bool skip_past_line(std::string_view marker);

  /// An `int` field in [lo, hi]; `what` names it in messages.
  long long integer(const std::string& what, long long lo, long long hi);
  /// A `size_t` field in [lo, hi].
  std::uint64_t count(const std::string& what, std::uint64_t lo, std::uint64_t hi);
  /// A `double` field; `finite` refuses NaN and infinities.
  double real(const std::string& what, bool finite);

  /// Largest number of entries of `min_bytes` bytes each (ASCII: `min_words` words) that the
  /// rest of the file can hold: bounds a count before anything is allocated for it.
  std::uint64_t capacity(std::size_t min_words, std::size_t min_bytes) const;

  /// Throws InputError "path:line: message" at the current position (or at `at`).
  [[noreturn]] void fail(const std::string& message) const { fail_at(pos_, message); }
  [[noreturn]] void fail_at(std::size_t at, const std::string& message) const;
  const std::string& path() const { return path_; }

private:
  void skip_space();
  const unsigned char* take(std::size_t bytes, const std::string& what);
  /// One field: `Stored` in binary sections, an ASCII word parsed as T otherwise.
  template <class Stored, class T>
  T field(const std::string& what, const char* kind, std::size_t before);
  template <class T>
  void check_range(const std::string& what, T v, T lo, T hi, std::size_t before) const;

  std::string path_;
  std::string_view text_;
  std::size_t pos_ = 0;
  bool binary_ = false;
};

} // namespace bipot::msh
