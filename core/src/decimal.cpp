#include "cutcom/decimal.hpp"

#include <cstdlib>
#include <stdexcept>

namespace cutcom {

void Decimal::out_of_range() { throw std::overflow_error("value out of range"); }

Decimal Decimal::scaled(std::int64_t num, std::int64_t den, bool* exact) const {
  Int128 p = units_ * num;
  Int128 q = p / den, rem = p % den;
  if (exact) *exact = rem == 0;
  Int128 twice = rem < 0 ? -2 * rem : 2 * rem;
  if (twice >= (den < 0 ? -den : den)) q += (p < 0) != (den < 0) ? -1 : 1;
  return checked(q);
}

Decimal::ParseResult Decimal::parse(std::string_view s) {
  ParseResult r;
  const char* p = s.data();
  const char* end = p + s.size();
  Decimal v;
  if (!read(p, end, v, r.error)) return r;
  if (p != end) return r;  // kSyntax: something after the number
  r.value = v;
  return r;
}

std::optional<std::int64_t> Decimal::to_integer() const {
  if (units_ >= INT64_MIN && units_ <= INT64_MAX) {  // 64-bit division: most values are small
    auto u = static_cast<std::int64_t>(units_);
    if (u % kUnitsPerOne != 0) return std::nullopt;
    return u / kUnitsPerOne;
  }
  if (units_ % kUnitsPerOne != 0) return std::nullopt;
  Int128 v = units_ / kUnitsPerOne;
  if (v > INT64_MAX || v < INT64_MIN) return std::nullopt;
  return static_cast<std::int64_t>(v);
}

double Decimal::to_double_rounded() const {
  // strtod of the exact text "<units>e-9" rounds correctly; a stack buffer keeps it allocation-free.
  char buf[64];
  char* end = buf + sizeof buf;
  char* p = end;
  *--p = '\0';
  for (const char* tail = "9-e"; *tail != '\0'; ++tail) *--p = *tail;
  Int128 a = units_ < 0 ? -units_ : units_;
  do {
    *--p = static_cast<char>('0' + static_cast<int>(a % 10));
    a /= 10;
  } while (a != 0);
  if (units_ < 0) *--p = '-';
  return std::strtod(p, nullptr);
}

std::string int128_to_string(Int128 v) {
  if (v == 0) return "0";
  bool negative = v < 0;
  std::string out;
  while (v != 0) {
    int digit = static_cast<int>(v % 10);
    out.push_back(static_cast<char>('0' + (digit < 0 ? -digit : digit)));
    v /= 10;
  }
  if (negative) out.push_back('-');
  return {out.rbegin(), out.rend()};
}

std::string Decimal::to_string() const {
  Int128 a = units_ < 0 ? -units_ : units_;
  std::string out = units_ < 0 ? "-" : "";
  out += int128_to_string(a / kUnitsPerOne);
  Int128 frac = a % kUnitsPerOne;
  if (frac != 0) {
    std::string digits = int128_to_string(frac);
    digits.insert(0, static_cast<std::size_t>(kFractionDigits) - digits.size(), '0');
    while (digits.back() == '0') digits.pop_back();
    out += "." + digits;
  }
  return out;
}

}  // namespace cutcom
