// NC-GRID-1: a value that is not a decimal (the sine of a programmed angle, the tangent point of
// a rounding, the centre of a circle through three points) goes onto the program's 10^-9 grid,
// correctly rounded. It is enclosed by interval arithmetic (MPFI) at a rising precision until the
// enclosure decides the rounding: one rule, in core, that both engines then read as decimals.
#pragma once

#include <mpfi.h>

#include <array>
#include <cstddef>
#include <stdexcept>

#include "cutcom/decimal.hpp"

namespace cutcom::grid {

// Thrown inside an evaluation when the working precision cannot decide a sign; the evaluation is
// repeated at a higher precision (to_grid).
struct Undecided {};

// A closed interval that encloses an exact real value, at the working precision of to_grid.
class Interval {
 public:
  Interval();  // [0, 0]
  explicit Interval(Decimal d);
  static Interval integer(long v);
  Interval(const Interval& o);
  Interval& operator=(const Interval& o);
  ~Interval();

  friend Interval operator+(const Interval& a, const Interval& b);
  friend Interval operator-(const Interval& a, const Interval& b);
  friend Interval operator*(const Interval& a, const Interval& b);
  friend Interval operator/(const Interval& a, const Interval& b);  // throws Undecided if b may be 0
  friend Interval operator-(const Interval& a);
  friend Interval sqrt(const Interval& a);                      // of max(a, 0): a rounding error below 0 is 0
  friend Interval atan2(const Interval& y, const Interval& x);  // radians

  // Sine and cosine of an angle in degrees; exact where the value is rational (multiples of 30°,
  // Niven's theorem: no other rational angle in degrees has a rational sine).
  static Interval sin_deg(Decimal degrees);
  static Interval cos_deg(Decimal degrees);
  static Interval pi();

  // -1, 0 or +1 if the enclosure decides it; otherwise Undecided below the last precision, and at
  // the last precision 0 (NC-GRID-1: a quantity not told from 0 at 4096 bits is taken as 0).
  int sign() const;
  bool is_point() const;  // the value is known exactly

  mpfi_t value;
};

// The working precision, in bits, of the evaluation in progress.
mpfr_prec_t precision();

namespace detail {
bool round_all(const Interval* values, std::size_t n, Decimal* out, bool last);
void set_precision(mpfr_prec_t bits);
constexpr mpfr_prec_t kFirstPrecision = 128;
constexpr mpfr_prec_t kLastPrecision = 4096;
}  // namespace detail

// NC-GRID-1: evaluates `f` (returning std::array<Interval, N>) at 128, 256, … 4096 bits until every
// value's rounding to the grid (nearest 10^-9, halves away from zero) is decided. At 4096 bits an
// enclosure that still contains a half-unit point is taken as that tie. Throws std::overflow_error
// beyond the decimal range.
template <std::size_t N, class F>
std::array<Decimal, N> to_grid(F&& f) {
  std::array<Decimal, N> out{};
  for (mpfr_prec_t p = detail::kFirstPrecision;; p *= 2) {
    bool last = p >= detail::kLastPrecision;
    detail::set_precision(p);
    try {
      std::array<Interval, N> v = f();
      if (detail::round_all(v.data(), N, out.data(), last)) return out;
    } catch (const Undecided&) {
      if (last) throw std::logic_error("NC-GRID-1: undecided at the last precision");
    }
  }
}

}  // namespace cutcom::grid
