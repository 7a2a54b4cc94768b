// Exact decimal numbers as written in an NC program (spec NC-NUM-1).
// A value is an integer count of 10^-9 units, so every literal with up to nine decimal places
// is held exactly and sums (G91, AC/IC, radius + wear + OFFN) stay exact.
#pragma once

#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace cutcom {

__extension__ typedef __int128 Int128;

class Decimal {
 public:
  static constexpr int kFractionDigits = 9;
  static constexpr std::int64_t kUnitsPerOne = 1'000'000'000;
  // Largest magnitude accepted from the program text: 10^12 (mm, degrees, feed units).
  static constexpr Int128 kMaxUnits = Int128(1'000'000'000'000) * kUnitsPerOne;

  constexpr Decimal() = default;
  static constexpr Decimal from_units(Int128 units) {
    Decimal d;
    d.units_ = units;
    return d;
  }
  static constexpr Decimal from_int(std::int64_t v) { return from_units(Int128(v) * kUnitsPerOne); }
  // The magnitude of integer.fraction in units, where `fraction` has `places` digits (at most
  // kFractionDigits): how a number read from text is valued (read(), the reader's plain blocks).
  // (The scales are a static table: one local to the function was written to the stack at each
  // call, eight stores per number read.)
  static constexpr std::uint64_t kFractionScale[] = {1'000'000'000, 100'000'000, 10'000'000, 1'000'000, 100'000,
                                                     10'000,        1'000,       100,        10,        1};
  static constexpr Int128 units_of(std::uint64_t integer, std::uint64_t fraction, int places) {
    static_assert(kFractionDigits == 9 && kUnitsPerOne == 1'000'000'000);
    return Int128(integer) * kUnitsPerOne + Int128(fraction * kFractionScale[places]);
  }

  // Why parsing fails, for the reader's error message.
  enum class ParseError { kSyntax, kTooManyDecimals, kOutOfRange };
  struct ParseResult;
  // Parses [+-]digits[.digits] or [+-].digits; never goes through floating point.
  static ParseResult parse(std::string_view text);
  // The same number read from p on: p is left after its digits (what follows is the caller's,
  // parse() requires the end). False with `error` where parse() fails on the same characters.
  // Inline: the reader values every coordinate of every block with it.
  static bool read(const char*& p, const char* end, Decimal& out, ParseError& error);

  constexpr Int128 units() const { return units_; }
  constexpr bool is_zero() const { return units_ == 0; }
  constexpr int sign() const { return units_ > 0 ? 1 : (units_ < 0 ? -1 : 0); }
  // Whole number if the value is integral and fits, else nullopt.
  std::optional<std::int64_t> to_integer() const;
  // Nearest double (correctly rounded); for the fast engine and for output only. Up to 2^53
  // units both the units and 10^9 are exact doubles, and IEEE division of exact operands rounds
  // correctly (inline: the engines convert every coordinate of every block).
  double to_double() const {
    constexpr Int128 kExact = Int128(1) << 53;
    __extension__ typedef unsigned __int128 Width;  // one comparison for -kExact <= units_ <= kExact
    if (static_cast<Width>(units_ + kExact) <= static_cast<Width>(2 * kExact))
      return static_cast<double>(static_cast<std::int64_t>(units_)) / static_cast<double>(kUnitsPerOne);
    return to_double_rounded();
  }
  // Exact decimal text, trailing zeros removed ("12.5", "-0.001", "3").
  std::string to_string() const;

  // value * num / den on the 10^-9 grid, rounded to the nearest unit (half away from zero), for
  // the unit and diameter conversions of the reader (NC-UNIT-2); `exact` says whether it was.
  Decimal scaled(std::int64_t num, std::int64_t den, bool* exact = nullptr) const;
  // value * factor on the grid (NC-UNIT-2); |factor| must stay below 9.2e9 (frames allow 1000).
  Decimal times(Decimal factor) const {
    return factor == from_int(1)    ? *this
           : factor == from_int(-1) ? -*this
                                    : scaled(static_cast<std::int64_t>(factor.units()), kUnitsPerOne);
  }

  // Checked arithmetic: throws std::overflow_error beyond kMaxUnits * 1000.
  // Inline: the reader adds frames and offsets to every coordinate of every block.
  friend Decimal operator+(Decimal a, Decimal b) { return checked(a.units_ + b.units_); }
  friend Decimal operator-(Decimal a, Decimal b) { return checked(a.units_ - b.units_); }
  friend constexpr Decimal operator-(Decimal a) { return from_units(-a.units_); }
  friend constexpr bool operator==(Decimal a, Decimal b) = default;
  friend constexpr std::strong_ordering operator<=>(Decimal a, Decimal b) {
    return a.units_ < b.units_   ? std::strong_ordering::less
           : a.units_ > b.units_ ? std::strong_ordering::greater
                                 : std::strong_ordering::equal;
  }

 private:
  double to_double_rounded() const;  // to_double beyond 2^53 units
  // Sums of program values may grow past the literal limit (many G91 steps); 1000x leaves room
  // while staying far from Int128 overflow.
  static constexpr Int128 kArithmeticLimit = kMaxUnits * 1000;
  static Decimal checked(Int128 v) {
    if (v > kArithmeticLimit || v < -kArithmeticLimit) out_of_range();
    return from_units(v);
  }
  [[noreturn]] static void out_of_range();
  // Held at 8-byte alignment: a block's words and modal state hold dozens of decimals, and at
  // 16 bytes each optional or flag beside one took 16 more (issue "Performance": every byte of a
  // block the reader fills crosses to the engine's core).
  __extension__ typedef __int128 Units __attribute__((aligned(8)));
  Units units_ = 0;
};

struct Decimal::ParseResult {
  std::optional<Decimal> value;
  ParseError error = ParseError::kSyntax;
};

// The digits are summed in 64 bits: the integer part stops at 10^12 and the fraction has at most
// nine digits, far inside the range; units go to 128 bits once.
inline bool Decimal::read(const char*& p, const char* end, Decimal& out, ParseError& error) {
  constexpr std::uint64_t kMaxInteger = static_cast<std::uint64_t>(kMaxUnits / kUnitsPerOne);
  bool negative = false;
  if (p < end && (*p == '+' || *p == '-')) negative = *p++ == '-';
  std::uint64_t integer = 0;
  const char* digits = p;
  for (; p < end && *p >= '0' && *p <= '9'; ++p) {
    integer = integer * 10 + static_cast<std::uint64_t>(*p - '0');
    if (integer > kMaxInteger) return error = ParseError::kOutOfRange, false;
  }
  bool any = p != digits;
  std::uint64_t fraction = 0;
  int frac_digits = 0;
  if (p < end && *p == '.') {
    ++p;
    for (; p < end && *p >= '0' && *p <= '9'; ++p) {
      any = true;
      if (frac_digits == kFractionDigits) {
        // Trailing zeros beyond nine places change nothing; anything else cannot be held exactly.
        if (*p != '0') return error = ParseError::kTooManyDecimals, false;
        continue;
      }
      fraction = fraction * 10 + static_cast<std::uint64_t>(*p - '0');
      ++frac_digits;
    }
  }
  if (!any) return error = ParseError::kSyntax, false;
  Int128 units = units_of(integer, fraction, frac_digits);
  if (units > kMaxUnits) return error = ParseError::kOutOfRange, false;
  out = from_units(negative ? -units : units);
  return true;
}

// Decimal text of a 128-bit integer (no such std::to_string).
std::string int128_to_string(Int128 v);

}  // namespace cutcom
