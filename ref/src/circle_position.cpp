#include "circle_position.hpp"

#include <mpfr.h>

#include <cmath>

namespace cutcom::ref {

CGAL::Sign CircleFrame::turn_sign(const Vector& a, const Vector& b) const {
  CGAL::Sign s = CGAL::sign(a.x() * b.y() - a.y() * b.x());
  return sense_ > 0 ? s : -s;
}

int CircleFrame::half(const Vector& v) const {
  CGAL::Sign s = turn_sign(u_, v);
  if (s != CGAL::ZERO) return s == CGAL::POSITIVE ? 0 : 1;
  return CGAL::sign(u_ * v) == CGAL::POSITIVE ? 0 : 1;  // along u: 0; opposite: pi
}

CGAL::Sign CircleFrame::compare_in_turn(const Vector& a, const Vector& b) const {
  int ha = half(a), hb = half(b);
  if (ha != hb) return ha < hb ? CGAL::NEGATIVE : CGAL::POSITIVE;
  // Within a half turn the rotation from a to b is less than pi: its sense orders them.
  return -turn_sign(a, b);
}

CirclePosition CircleFrame::signed_from(const CirclePosition& p, const Vector& v) const {
  if (turn_sign(p.v, v) == CGAL::NEGATIVE)  // backwards by less than pi
    return {p.turns - (compare_in_turn(v, p.v) == CGAL::POSITIVE ? 1 : 0), v};
  return {p.turns + (compare_in_turn(v, p.v) == CGAL::NEGATIVE ? 1 : 0), v};  // forwards, up to pi
}

CirclePosition CircleFrame::forward_from(const CirclePosition& p, const Vector& v) const {
  return {p.turns + (compare_in_turn(v, p.v) == CGAL::NEGATIVE ? 1 : 0), v};
}

CGAL::Sign CircleFrame::compare(const CirclePosition& a, const CirclePosition& b) const {
  if (a.turns != b.turns) return a.turns < b.turns ? CGAL::NEGATIVE : CGAL::POSITIVE;
  return compare_in_turn(a.v, b.v);
}

double CircleFrame::radians(const CirclePosition& from, const CirclePosition& to) const {
  CGAL::Sign in_turn = compare_in_turn(to.v, from.v);
  double ax = CGAL::to_double(from.v.x()), ay = CGAL::to_double(from.v.y());
  double bx = CGAL::to_double(to.v.x()), by = CGAL::to_double(to.v.y());
  // The rotation from `from` to `to` in (-pi, pi] on the nearest doubles, moved into the range
  // the exact comparison gives: (0, 2 pi) when `to` lies later in the turn, (-2 pi, 0) earlier.
  double d = std::atan2(sense_ * (ax * by - ay * bx), ax * bx + ay * by);
  const double pi = std::acos(-1.0);
  // A d of the wrong sign is a rounding at a tie (tiny) or a rotation past pi (atan2's range):
  // 1e-9 rad lies far above the one and far below the other.
  if (in_turn == CGAL::ZERO)
    d = 0;
  else if (in_turn == CGAL::POSITIVE && d <= 0)
    d = d > -1e-9 ? 0 : d + 2 * pi;
  else if (in_turn == CGAL::NEGATIVE && d >= 0)
    d = d < 1e-9 ? 0 : d - 2 * pi;
  return d + 2 * pi * static_cast<double>(to.turns - from.turns);
}

std::string CircleFrame::length_text(const CirclePosition& from, const CirclePosition& to, const FT& radius) const {
  CGAL::Sign s = compare(to, from);
  if (s == CGAL::ZERO) return "0";
  // The sign above is exact; the digits come from MPFR on the nearest doubles.
  mpfr_t a, r;
  mpfr_inits2(128, a, r, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(a, std::fabs(radians(from, to)), MPFR_RNDN);
  mpfr_set_d(r, CGAL::to_double(radius), MPFR_RNDN);
  mpfr_mul(a, a, r, MPFR_RNDN);
  mpfr_div_ui(a, a, 1'000'000'000UL, MPFR_RNDN);  // units -> mm
  char buf[64];
  mpfr_snprintf(buf, sizeof buf, "%.17Re", a);
  mpfr_clears(a, r, static_cast<mpfr_ptr>(nullptr));
  return (s == CGAL::NEGATIVE ? "-" : "") + std::string(buf);
}

}  // namespace cutcom::ref
