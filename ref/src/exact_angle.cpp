#include "exact_angle.hpp"

#include <mpfr.h>

namespace cutcom::ref {

namespace {

// Half 0: arg in [0, pi); half 1: arg in [pi, 2 pi).
int half(const FT& x, const FT& y) {
  CGAL::Sign sy = CGAL::sign(y);
  if (sy == CGAL::POSITIVE) return 0;
  if (sy == CGAL::NEGATIVE) return 1;
  return CGAL::sign(x) == CGAL::POSITIVE ? 0 : 1;
}

// arg(u) < arg(v), both in [0, 2 pi).
bool arg_less(const FT& ux, const FT& uy, const FT& vx, const FT& vy) {
  int hu = half(ux, uy), hv = half(vx, vy);
  if (hu != hv) return hu < hv;
  return CGAL::sign(ux * vy - uy * vx) == CGAL::POSITIVE;
}

}  // namespace

ExactAngle operator+(const ExactAngle& a, const ExactAngle& b) {
  ExactAngle s;
  s.x = a.x * b.x - a.y * b.y;
  s.y = a.x * b.y + a.y * b.x;
  // arg(a) + arg(b) passes 2 pi exactly when the product's arg falls below arg(a).
  s.turns = a.turns + b.turns + (arg_less(s.x, s.y, a.x, a.y) ? 1 : 0);
  return s;
}

ExactAngle operator-(const ExactAngle& a) {
  bool zero_arg = CGAL::sign(a.y) == CGAL::ZERO && CGAL::sign(a.x) == CGAL::POSITIVE;
  return {zero_arg ? -a.turns : -a.turns - 1, a.x, -a.y};
}

CGAL::Sign ExactAngle::sign() const {
  if (turns > 0) return CGAL::POSITIVE;
  if (turns < 0) return CGAL::NEGATIVE;
  bool zero_arg = CGAL::sign(y) == CGAL::ZERO && CGAL::sign(x) == CGAL::POSITIVE;
  return zero_arg ? CGAL::ZERO : CGAL::POSITIVE;
}

ExactAngle ExactAngle::rotation(const Vector& from, const Vector& to, int sense) {
  // conj(from) * to, conjugated again for clockwise rotation.
  FT x = from.x() * to.x() + from.y() * to.y();
  FT y = from.x() * to.y() - from.y() * to.x();
  return {0, x, sense > 0 ? y : -y};
}

ExactAngle ExactAngle::signed_rotation(const Vector& from, const Vector& to, int sense) {
  ExactAngle r = rotation(from, to, sense);
  if (CGAL::sign(r.y) == CGAL::NEGATIVE) r.turns = -1;  // arg in (pi, 2 pi) means a negative rotation
  return r;
}

std::string arc_length_text(const ExactAngle& angle, const FT& radius) {
  CGAL::Sign s = angle.sign();
  if (s == CGAL::ZERO) return "0";
  // The sign above is exact; the digits come from MPFR on the nearest doubles.
  mpfr_t x, y, r, a, pi;
  mpfr_inits2(128, x, y, r, a, pi, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(x, CGAL::to_double(angle.x), MPFR_RNDN);  // digits only: the nearest doubles suffice
  mpfr_set_d(y, CGAL::to_double(angle.y), MPFR_RNDN);
  mpfr_set_d(r, CGAL::to_double(radius), MPFR_RNDN);
  mpfr_atan2(a, y, x, MPFR_RNDN);
  mpfr_const_pi(pi, MPFR_RNDN);
  if (mpfr_sgn(a) < 0) mpfr_add(a, a, pi, MPFR_RNDN), mpfr_add(a, a, pi, MPFR_RNDN);
  mpfr_mul_ui(pi, pi, 2, MPFR_RNDN);
  mpfr_mul_si(pi, pi, angle.turns, MPFR_RNDN);
  mpfr_add(a, a, pi, MPFR_RNDN);
  mpfr_mul(a, a, r, MPFR_RNDN);
  mpfr_div_ui(a, a, 1'000'000'000UL, MPFR_RNDN);  // units -> mm
  mpfr_abs(a, a, MPFR_RNDN);
  char buf[64];
  mpfr_snprintf(buf, sizeof buf, "%.17Re", a);
  mpfr_clears(x, y, r, a, pi, static_cast<mpfr_ptr>(nullptr));
  return (s == CGAL::NEGATIVE ? "-" : "") + std::string(buf);
}

}  // namespace cutcom::ref
