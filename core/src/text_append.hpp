// Appending numbers and padded fields to a text buffer without a formatting library call per
// number: the writers emit millions of numbers (issue "Performance": fmt took 61 % of a run).
// The digits are those of std::to_chars, which print correctly rounded values, as fmt's did.
#pragma once

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace cutcom::text {

// "00" "01" … "99": two digits per division (the writers' hottest loop).
inline constexpr char kPairs[] =
    "0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546474849"
    "5051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899";

// An integer's digits at `p` (room for 20 characters); returns the end. The writers put several
// per element (block numbers, lines, the element's count); most are below 10^8, written by pairs
// after their length is known, the rest by std::to_chars (the same digits).
inline char* put_integer(char* p, std::int64_t v) {
  if (v < 0 || v >= 100000000) return std::to_chars(p, p + 20, v).ptr;
  auto x = static_cast<std::uint32_t>(v);
  int length = x < 10         ? 1
               : x < 100      ? 2
               : x < 1000     ? 3
               : x < 10000    ? 4
               : x < 100000   ? 5
               : x < 1000000  ? 6
               : x < 10000000 ? 7
                              : 8;
  char* end = p + length;
  char* q = end;
  for (; x >= 100; x /= 100) q -= 2, std::memcpy(q, kPairs + 2 * (x % 100), 2);
  if (x >= 10)
    std::memcpy(q - 2, kPairs + 2 * x, 2);
  else
    q[-1] = static_cast<char>('0' + x);
  return end;
}

inline void append_integer(std::string& out, std::int64_t v) {
  char digits[24];
  out.append(digits, put_integer(digits, v));
}

// Fixed notation with `places` decimals ("-12.3400" for places 4), the digits of std::to_chars,
// written at `p` (room for 352 characters); returns the end. Most values take a short path:
// scaled by 10^places below 2^40 the product is within 2^-13 of the exact one, so unless its
// fraction lies within 1e-3 of one half, rounding it to an integer gives to_chars's correctly
// rounded digits; the rest (ties, huge values, NaN) go to to_chars. The places are a template
// argument so that the divisions by 10^places are by a constant (the text writer's four).
template <int kPlaces>
inline char* put_fixed(char* p, double v) {
  static_assert(kPlaces >= 0 && kPlaces <= 6);
  constexpr std::uint64_t kPower = [] {
    std::uint64_t power = 1;
    for (int k = 0; k < kPlaces; ++k) power *= 10;
    return power;
  }();
  double y = std::fabs(v) * static_cast<double>(kPower);      // 10^places is exact
  if (y < 1099511627776.0) {                                  // 2^40; false for NaN and infinities
    std::uint64_t truncated = static_cast<std::uint64_t>(y);  // the floor: 0 <= y < 2^40
    double fraction = y - static_cast<double>(truncated);     // exact
    if (std::fabs(fraction - 0.5) > 1e-3) {
      // The digits of n = round(y) from the right by pairs, the point `kPlaces` from the end, in
      // a scratch array; then one copy of fixed size (no length to count first: 3 % of a run).
      std::uint64_t n = truncated + (fraction > 0.5 ? 1 : 0);
      char scratch[48];  // the text ends at scratch + 24: at most 15 characters
      char* const end = scratch + 24;
      char* q = end;
      int k = 0;
      for (; k + 2 <= kPlaces; k += 2, n /= 100) q -= 2, std::memcpy(q, kPairs + 2 * (n % 100), 2);
      if (k < kPlaces) *--q = static_cast<char>('0' + n % 10), n /= 10;
      if (kPlaces > 0) *--q = '.';
      for (; n >= 100; n /= 100) q -= 2, std::memcpy(q, kPairs + 2 * (n % 100), 2);
      if (n >= 10)
        q -= 2, std::memcpy(q, kPairs + 2 * n, 2);
      else
        *--q = static_cast<char>('0' + n);
      if (std::signbit(v)) *--q = '-';
      std::memcpy(p, q, 24);  // q + 24 stays inside the scratch array
      return p + (end - q);
    }
  }
  return std::to_chars(p, p + 352, v, std::chars_format::fixed, kPlaces).ptr;
}

inline char* put_fixed(char* p, double v, int places) {
  switch (places) {
    case 0:
      return put_fixed<0>(p, v);
    case 1:
      return put_fixed<1>(p, v);
    case 2:
      return put_fixed<2>(p, v);
    case 3:
      return put_fixed<3>(p, v);
    case 4:
      return put_fixed<4>(p, v);
    case 5:
      return put_fixed<5>(p, v);
    case 6:
      return put_fixed<6>(p, v);
    default:
      return std::to_chars(p, p + 352, v, std::chars_format::fixed, places).ptr;
  }
}

inline void append_fixed(std::string& out, double v, int places) {
  char digits[352];  // the longest binary64 in fixed notation with up to 16 places
  out.append(digits, put_fixed(digits, v, places));
}

// The text at `p`; returns the end.
inline char* put(char* p, std::string_view s) {
  std::memcpy(p, s.data(), s.size());
  return p + s.size();
}

// put_shortest's short path: where v is the double nearest to a decimal of at most 6 places with
// 1e-3 <= |v| < 1e9, that decimal ("12.0", "-0.25"); nullptr for any other v. m = |v| * 1e6 rounds to the decimal's
// integer (m < 2^53, so m / 1e6 is correctly rounded and equals |v| exactly then; a wrong m fails that test), and as
// decimals of at most 15 digits map to distinct doubles, its digits without trailing zeros are
// the shortest that read back as v. Written at `p` (room for 20 characters).
inline char* put_short_decimal(char* p, double v) {
  double a = std::fabs(v);
  if (!(a >= 1e-3 && a < 1e9)) return nullptr;
  auto m = static_cast<std::uint64_t>(a * 1e6 + 0.5);  // a truncation: no rounding-mode call
  if (static_cast<double>(m) / 1e6 != a) return nullptr;
  auto integer = static_cast<std::int64_t>(m / 1000000);
  auto fraction = static_cast<std::uint32_t>(m % 1000000);
  if (std::signbit(v)) *p++ = '-';
  p = put_integer(p, integer);
  *p++ = '.';
  if (fraction == 0) {
    *p++ = '0';
    return p;
  }
  // The six places by pairs, then as many as are not trailing zeros: the highest byte that is no
  // '0' (the two bytes after the places are '0' too), found from the bit width of their XOR.
  char places[8] = {0, 0, 0, 0, 0, 0, '0', '0'};
  std::memcpy(places, kPairs + 2 * (fraction / 10000), 2);
  std::memcpy(places + 2, kPairs + 2 * (fraction / 100 % 100), 2);
  std::memcpy(places + 4, kPairs + 2 * (fraction % 100), 2);
  std::uint64_t word;
  std::memcpy(&word, places, 8);
  if constexpr (std::endian::native == std::endian::big) word = __builtin_bswap64(word);
  std::memcpy(p, places, 8);  // whole: the caller's room holds it
  return p + (std::bit_width(word ^ 0x3030303030303030u) + 7) / 8;
}

// The 17 digits of v < 10^17, with leading zeros, at `p`: a fixed number of pairs, no loop
// (a double's shortest significand has at most 17 digits).
inline void put_17_digits(char* p, std::uint64_t v) {
  std::uint64_t high = v / 100000000;  // at most 9 digits
  auto low = static_cast<std::uint32_t>(v % 100000000);
  auto top = static_cast<std::uint32_t>(high / 100000000);  // 1 digit
  auto middle = static_cast<std::uint32_t>(high % 100000000);
  auto put8 = [](char* q, std::uint32_t x) {
    std::uint32_t a = x / 10000, b = x % 10000;
    std::memcpy(q, kPairs + 2 * (a / 100), 2);
    std::memcpy(q + 2, kPairs + 2 * (a % 100), 2);
    std::memcpy(q + 4, kPairs + 2 * (b / 100), 2);
    std::memcpy(q + 6, kPairs + 2 * (b % 100), 2);
  };
  p[0] = static_cast<char>('0' + top);
  put8(p + 1, middle);
  put8(p + 9, low);
}

// A JSON number (docs/json-format.md): the shortest decimal that reads back as the same double,
// and of those the nearest (Dragonbox, through fmt, which prints its doubles by it; the digits
// are std::to_chars's, tests/text_append_test.cpp), laid out as nlohmann::json lays out a double:
// fixed for 1e-4 <= |v| < 1e15 ("12.0", "0.0012"), else "1.25e-05", "3e+20"; "-0.0" for -0.
// (nlohmann's own Grisu2 digits are one longer for about one double in 2,000.) NaN and
// infinities are no JSON numbers: the caller writes null. Written at `p` (room for 32
// characters); returns the end.
inline char* put_shortest(char* p, double v) {
  if (char* end = put_short_decimal(p, v)) return end;
  if (v == 0) return put(p, std::signbit(v) ? std::string_view("-0.0") : std::string_view("0.0"));
  if (!std::isfinite(v)) return std::to_chars(p, p + 32, v).ptr;
  auto decimal = fmt::detail::dragonbox::to_decimal(std::fabs(v));  // significand * 10^exponent
  // The significand's digits: how many from its bit width (log10 2 ~ 1233 / 4096, then one
  // comparison), so no loop strips leading zeros.
  static constexpr std::uint64_t kPowers[] = {1,
                                              10,
                                              100,
                                              1000,
                                              10000,
                                              100000,
                                              1000000,
                                              10000000,
                                              100000000,
                                              1000000000,
                                              10000000000,
                                              100000000000,
                                              1000000000000,
                                              10000000000000,
                                              100000000000000,
                                              1000000000000000,
                                              10000000000000000,
                                              100000000000000000};
  const std::uint64_t significand = decimal.significand;  // not 0, below 10^17
  int estimate = (static_cast<int>(std::bit_width(significand)) * 1233) >> 12;
  int count = estimate + (significand >= kPowers[estimate] ? 1 : 0);
  char padded[40]{};  // 17 digits, then room for the fixed-size copies below to read past them
  put_17_digits(padded, significand);
  const char* digits = padded + 17 - count;
  int point = count + decimal.exponent;  // the decimal point's place after the first digit
  // Laid out in a scratch array by copies of fixed size (each a few moves, where a copy of the
  // exact length is a library call), then copied whole: at most 24 characters.
  char text[64];
  char* q = text;
  if (std::signbit(v)) *q++ = '-';
  if (point <= -4 || point > 15) {  // d.ddde+XX
    q[0] = digits[0];
    if (count > 1) q[1] = '.', std::memcpy(q + 2, digits + 1, 16), q += count;
    q += 1;
    int exponent = point - 1;
    *q++ = 'e';
    *q++ = exponent < 0 ? '-' : '+';
    if (exponent < 0) exponent = -exponent;
    if (exponent >= 100) *q++ = static_cast<char>('0' + exponent / 100), exponent %= 100;
    std::memcpy(q, kPairs + 2 * exponent, 2);
    q += 2;
  } else if (point <= 0) {  // 0.[000]digits
    std::memcpy(q, "0.000", 5);
    q += 2 - point;
    std::memcpy(q, digits, 17);
    q += count;
  } else if (count <= point) {  // digits[000].0
    std::memcpy(q, digits, 17);
    q += count;
    std::memcpy(q, "000000000000000", 15);
    q += point - count;
    *q++ = '.', *q++ = '0';
  } else {  // dig.its
    std::memcpy(q, digits, 17);
    q[point] = '.';
    std::memcpy(q + point + 1, digits + point, 17);
    q += count + 1;
  }
  std::memcpy(p, text, 24);
  return p + (q - text);
}

// `v` right-aligned in `width` characters at `p` ("{:>width}"); returns the end.
inline char* put_right_integer(char* p, std::int64_t v, std::size_t width) {
  char digits[24];
  auto n = static_cast<std::size_t>(put_integer(digits, v) - digits);
  for (; n < width; --width) *p++ = ' ';
  return put(p, std::string_view(digits, n));
}

// Spaces at `p` up to `width` characters since `field_start` ("{:<width}"); returns the end.
inline char* put_padding(char* p, const char* field_start, std::size_t width) {
  for (auto used = static_cast<std::size_t>(p - field_start); used < width; ++used) *p++ = ' ';
  return p;
}

}  // namespace cutcom::text
