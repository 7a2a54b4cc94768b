// Appending numbers and padded fields to a text buffer without a formatting library call per
// number: the writers emit millions of numbers (issue "Performance": fmt took 61 % of a run).
// The digits are those of std::to_chars, which print correctly rounded values, as fmt's did.
#pragma once

#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>

namespace cutcom::text {

inline void append_integer(std::string& out, std::int64_t v) {
  char digits[24];
  auto r = std::to_chars(digits, digits + sizeof digits, v);
  out.append(digits, r.ptr);
}

// Fixed notation with `places` decimals ("-12.3400" for places 4).
inline void append_fixed(std::string& out, double v, int places) {
  char digits[352];  // the longest binary64 in fixed notation with up to 16 places
  auto r = std::to_chars(digits, digits + sizeof digits, v, std::chars_format::fixed, places);
  out.append(digits, r.ptr);
}

// Spaces up to `width` characters since `field_start`, as "{:<width}" did (never truncates).
inline void pad_to(std::string& out, std::size_t field_start, std::size_t width) {
  std::size_t used = out.size() - field_start;
  if (used < width) out.append(width - used, ' ');
}

// "{:>width}": the text right-aligned in `width` characters.
inline void append_right(std::string& out, std::string_view s, std::size_t width) {
  if (s.size() < width) out.append(width - s.size(), ' ');
  out.append(s);
}

inline void append_right_integer(std::string& out, std::int64_t v, std::size_t width) {
  char digits[24];
  auto r = std::to_chars(digits, digits + sizeof digits, v);
  append_right(out, std::string_view(digits, static_cast<std::size_t>(r.ptr - digits)), width);
}

}  // namespace cutcom::text
