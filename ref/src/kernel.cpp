#include "kernel.hpp"

#include <fmt/format.h>
#include <mpfr.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>

namespace cutcom::ref {

FT leaf(const Decimal& d) {
  Int128 u = d.units();
  if (u >= LONG_MIN && u <= LONG_MAX) return FT(static_cast<long>(u));
  return FT(CORE::BigInt(to_mpz(d).get_mpz_t()));
}

Point plane_point(const Point3& p, PlaneAxes axes) {
  return Point(leaf(coord(p, axes.abscissa)), leaf(coord(p, axes.ordinate)));
}

namespace {
// PATH-ELEMENT-2, the usual case: CORE approximates the value to `prec` bits relative (|v - a| <=
// 2^-prec |v|, a a BigFloat (m +- err) 2^(CHUNK_BIT exp)), so v lies in an interval around a; where
// both ends of the interval round to one double, so does v (rounding to nearest is monotone).
// Empty where a midpoint between two doubles may lie inside, or outside the normal range: the
// exact comparisons below decide then. One approximation instead of two exact comparisons with
// midpoints, which took half of ref's time on a plain contour.
// `divisor` (> 0): the double nearest to value / divisor, the interval's ends divided with outward
// rounding (no new expression node, and the value's own approximation is kept by CORE for the next
// time: a point is output as one element's end and the next one's start).
std::optional<double> nearest_from_interval(const FT& value, long prec, unsigned long divisor = 1) {
  CORE::BigFloat a = value.approx(prec, CORE::extLong::getPosInfty()).BigFloatValue();
  if (sign(a.m()) == 0 && a.err() == 0) return 0.0;
  mpz_class m(a.m().get_mp()), err(static_cast<unsigned long>(a.err()));
  long shift = CORE::CHUNK_BIT * a.exp();
  auto bits = static_cast<mpfr_prec_t>(mpz_sizeinbase(m.get_mpz_t(), 2) + 66);
  mpfr_t lo, hi, slack;
  mpfr_inits2(bits, lo, hi, slack, static_cast<mpfr_ptr>(nullptr));
  mpz_class m_lo = m - err, m_hi = m + err;
  mpfr_set_z_2exp(lo, m_lo.get_mpz_t(), shift, MPFR_RNDD);
  mpfr_set_z_2exp(hi, m_hi.get_mpz_t(), shift, MPFR_RNDU);
  // |v - a| <= 2^-prec |v| gives |v - a| <= 2^(1-prec) |a| (prec >= 2); widened by one more bit.
  mpfr_abs(slack, mpfr_cmpabs(lo, hi) > 0 ? lo : hi, MPFR_RNDU);
  mpfr_mul_2si(slack, slack, 2 - prec, MPFR_RNDU);
  mpfr_sub(lo, lo, slack, MPFR_RNDD);
  mpfr_add(hi, hi, slack, MPFR_RNDU);
  if (divisor != 1) mpfr_div_ui(lo, lo, divisor, MPFR_RNDD), mpfr_div_ui(hi, hi, divisor, MPFR_RNDU);
  double dl = mpfr_get_d(lo, MPFR_RNDN), dh = mpfr_get_d(hi, MPFR_RNDN);
  mpfr_clears(lo, hi, slack, static_cast<mpfr_ptr>(nullptr));
  if (dl != dh || !std::isfinite(dl) || std::fabs(dl) < DBL_MIN) return std::nullopt;
  return dl;
}
}  // namespace

// The filter of d, the double nearest to v, with maxAbs = 2|d| and ind = 2: an error bound of
// maxAbs * ind * 2^-53 = 2^-51 |d|. Sound as CORE's filters require (Burnikel, Funke, Schirra):
// |d - v| <= 2^-53 |v| (a nearest double in the normal range) lies below that bound, |v| and |d|
// are at most maxAbs, and d has v's sign. The double only bounds the filter; the signs it then
// decides are exact, as every sign CORE's filter decides.
bool filter_by_nearest(const FT& v) {
  std::optional<double> d = nearest_from_interval(v, 96);
  if (!d || !std::isnormal(*d)) return false;
  v.Rep()->ffVal = CORE::filteredFp(*d, 2 * std::fabs(*d), 2);
  return true;
}

void settle_filter(const FT& v, CGAL::Sign exact) {
  if (exact == CGAL::ZERO || v.Rep()->ffVal.isOK()) return;
  if (!filter_by_nearest(v))
    v.Rep()->ffVal = CORE::filteredFp(static_cast<int>(exact), std::numeric_limits<double>::infinity(), 1);
}

double nearest_double(const FT& value) {
  if (auto d = nearest_from_interval(value, 96)) return *d;
  double d = CGAL::to_double(value);
  // 0: CORE's relative approximation found the value's sign zero (or below every double).
  if (d == 0 || !std::isfinite(d)) return d;
  // d is within an ulp or two: step to the neighbour until the value lies between the midpoints
  // to d's neighbours (exact comparisons with dyadic rationals, never a zero test of the value
  // unless it is exactly such a midpoint).
  for (;;) {
    double below = std::nextafter(d, -HUGE_VAL), above = std::nextafter(d, HUGE_VAL);
    FT low = (FT(below) + FT(d)) / FT(2), high = (FT(d) + FT(above)) / FT(2);
    CGAL::Comparison_result at_low = CGAL::compare(value, low);
    if (at_low == CGAL::SMALLER) {
      d = below;
      continue;
    }
    CGAL::Comparison_result at_high = CGAL::compare(value, high);
    if (at_high == CGAL::LARGER) {
      d = above;
      continue;
    }
    // A tie goes to the neighbour with an even last digit.
    auto even = [](double x) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      return (bits & 1U) == 0;
    };
    if (at_low == CGAL::EQUAL && !even(d)) return below;
    if (at_high == CGAL::EQUAL && !even(d)) return above;
    return d;
  }
}

double nearest_mm(const FT& units) {
  if (auto d = nearest_from_interval(units, 96, 1'000'000'000UL)) return *d;
  return nearest_double(units / FT(1'000'000'000L));
}

std::string exact_text(const FT& value) {
  if (CGAL::sign(value) == CGAL::ZERO) return "0";
  // The sign is exact (CORE); the digits are 17 of CORE's double approximation, within an ulp or
  // two of the value: two ways of building one value may differ in the last digit. Rounding to
  // the nearest double (nearest_double) made campaigns 20 % slower. Not Expr::toString: after exact
  // zero tests an approximation may hold thousands of bits, and printing all of them dominated
  // ref's run time.
  auto magnitude = std::fabs(CGAL::to_double(value));
  return fmt::format("{}{:.17g}", CGAL::sign(value) == CGAL::NEGATIVE ? "-" : "", magnitude);
}

std::string exact_mm(const FT& units) { return exact_text(units / FT(1'000'000'000L)); }

}  // namespace cutcom::ref
