#include "contour_angle.hpp"

#include <mpfr.h>

#include <cmath>
#include <stdexcept>

#include "exact_root.hpp"
#include "kernel.hpp"

namespace cutcom::ref {

namespace {

// RAII for mpfr_t.
struct Mpfr {
  mpfr_t v;
  explicit Mpfr(mpfr_prec_t bits) { mpfr_init2(v, bits); }
  ~Mpfr() { mpfr_clear(v); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
};

FT to_ft_q(const mpq_class& q) { return FT(CORE::BigRat(q.get_mpq_t())); }

mpq_class threshold_rational(const Decimal& t) {
  mpq_class q(to_mpz(t), mpz_class(Decimal::kUnitsPerOne));
  q.canonicalize();
  return q;
}

// cos^2(T) when it is rational (T in degrees, 0 <= T <= 180), with the sign of cos(T).
bool special_cosine(const mpq_class& t, mpq_class& cos_squared, int& cos_sign) {
  if (t.get_den() != 1) return false;
  long deg = t.get_num().get_si();
  switch (deg) {
    case 0:
      cos_squared = 1;
      cos_sign = 1;
      return true;
    case 30:
      cos_squared = mpq_class(3, 4);
      cos_sign = 1;
      return true;
    case 45:
      cos_squared = mpq_class(1, 2);
      cos_sign = 1;
      return true;
    case 60:
      cos_squared = mpq_class(1, 4);
      cos_sign = 1;
      return true;
    case 90:
      cos_squared = 0;
      cos_sign = 0;
      return true;
    case 120:
      cos_squared = mpq_class(1, 4);
      cos_sign = -1;
      return true;
    case 135:
      cos_squared = mpq_class(1, 2);
      cos_sign = -1;
      return true;
    case 150:
      cos_squared = mpq_class(3, 4);
      cos_sign = -1;
      return true;
    case 180:
      cos_squared = 1;
      cos_sign = -1;
      return true;
    default:
      return false;
  }
}

// sign(cos T - cos theta) with cos theta = dot / sqrt(l2).
int sign_cos_difference(const mpz_class& dot, const mpz_class& l2, const mpq_class& t) {
  mpq_class c2;
  int cs = 0;
  int qs = sgn(dot);
  if (special_cosine(t, c2, cs)) {
    if (cs != qs) return cs > qs ? 1 : -1;
    if (cs == 0) return 0;
    mpq_class q2(dot * dot, l2);
    q2.canonicalize();
    int magnitude = cmp(c2, q2);  // sign(|cos T| - |cos theta|)
    return cs > 0 ? (magnitude > 0) - (magnitude < 0) : (magnitude < 0) - (magnitude > 0);
  }
  for (mpfr_prec_t bits = 128; bits <= (1 << 16); bits *= 2) {
    Mpfr arg(bits), cos_t(bits), q(bits), root(bits), diff(bits), bound(bits);
    mpfr_const_pi(arg.v, MPFR_RNDN);
    mpfr_mul_q(arg.v, arg.v, t.get_mpq_t(), MPFR_RNDN);
    mpfr_div_ui(arg.v, arg.v, 180, MPFR_RNDN);
    mpfr_cos(cos_t.v, arg.v, MPFR_RNDN);
    mpfr_set_z(root.v, l2.get_mpz_t(), MPFR_RNDN);
    mpfr_sqrt(root.v, root.v, MPFR_RNDN);
    mpfr_set_z(q.v, dot.get_mpz_t(), MPFR_RNDN);
    mpfr_div(q.v, q.v, root.v, MPFR_RNDN);
    mpfr_sub(diff.v, cos_t.v, q.v, MPFR_RNDN);
    // Each side is within 16 * 2^-bits of its true value (|arg| <= pi, a few roundings each).
    mpfr_set_ui_2exp(bound.v, 64, -bits, MPFR_RNDN);
    if (mpfr_cmpabs(diff.v, bound.v) > 0) return mpfr_sgn(diff.v);
  }
  throw std::logic_error("contour angle comparison did not separate (impossible by Niven's theorem)");
}

// theta - T in degrees as margin text, theta = atan2(|sine|, cosine) from MPFR values already set
// in `s` and `c`; the sign printed is the exact one decided by the caller.
std::string margin_degrees(Mpfr& s, Mpfr& c, const mpq_class& t, int exact_sign) {
  if (exact_sign == 0) return "0";
  Mpfr theta(192), pi(192);
  mpfr_abs(s.v, s.v, MPFR_RNDN);
  mpfr_atan2(theta.v, s.v, c.v, MPFR_RNDN);
  mpfr_const_pi(pi.v, MPFR_RNDN);
  mpfr_mul_ui(theta.v, theta.v, 180, MPFR_RNDN);
  mpfr_div(theta.v, theta.v, pi.v, MPFR_RNDN);
  mpfr_sub_q(theta.v, theta.v, t.get_mpq_t(), MPFR_RNDN);
  mpfr_abs(theta.v, theta.v, MPFR_RNDN);
  char buf[64];
  mpfr_snprintf(buf, sizeof buf, "%.17Re", theta.v);
  return (exact_sign < 0 ? "-" : "") + std::string(buf);
}

int sign_cos_difference_exact(const FT& dot, const FT& l2, const mpq_class& t) {
  mpq_class c2;
  int cs = 0;
  int qs = static_cast<int>(CGAL::sign(dot));
  if (special_cosine(t, c2, cs)) {
    if (cs != qs) return cs > qs ? 1 : -1;
    if (cs == 0) return 0;
    int magnitude = static_cast<int>(CGAL::compare(to_ft_q(c2), dot * dot / l2));
    return cs > 0 ? magnitude : -magnitude;
  }
  FT q = dot / exact_root(l2);
  for (mpfr_prec_t bits = 128; bits <= 4096; bits *= 2) {
    Mpfr arg(bits), cos_t(bits), bound(bits), lo(bits), hi(bits);
    mpfr_const_pi(arg.v, MPFR_RNDN);
    mpfr_mul_q(arg.v, arg.v, t.get_mpq_t(), MPFR_RNDN);
    mpfr_div_ui(arg.v, arg.v, 180, MPFR_RNDN);
    mpfr_cos(cos_t.v, arg.v, MPFR_RNDN);
    mpfr_set_ui_2exp(bound.v, 64, -bits, MPFR_RNDN);  // |cos_t - cos T| < 16 * 2^-bits, with room
    mpfr_sub(lo.v, cos_t.v, bound.v, MPFR_RNDD);
    mpfr_add(hi.v, cos_t.v, bound.v, MPFR_RNDU);
    mpq_class lq, hq;
    mpfr_get_q(lq.get_mpq_t(), lo.v);
    mpfr_get_q(hq.get_mpq_t(), hi.v);
    if (CGAL::compare(q, to_ft_q(lq)) == CGAL::SMALLER) return 1;  // cos theta < cos T
    if (CGAL::compare(q, to_ft_q(hq)) == CGAL::LARGER) return -1;
  }
  return 0;
}

}  // namespace

AngleComparison compare_contour_angle_exact(const FT& cross, const FT& dot, const FT& squared_lengths_product,
                                            const Decimal& threshold_degrees, bool with_margin) {
  mpq_class t = threshold_rational(threshold_degrees);
  AngleComparison r;
  r.sign = sign_cos_difference_exact(dot, squared_lengths_product, t);
  if (!with_margin) return r;
  // Digits only (the sign is decided above): the angle from the nearest doubles.
  Mpfr sine(192), cosine(192);
  mpfr_set_d(sine.v, CGAL::to_double(cross), MPFR_RNDN);
  mpfr_set_d(cosine.v, CGAL::to_double(dot), MPFR_RNDN);
  r.margin_text = margin_degrees(sine, cosine, t, r.sign);
  return r;
}

AngleComparison compare_contour_angle(const mpz_class& cross, const mpz_class& dot,
                                      const mpz_class& squared_lengths_product, const Decimal& threshold_degrees,
                                      bool with_margin) {
  mpq_class t = threshold_rational(threshold_degrees);
  AngleComparison r;
  // theta > T  <=>  cos theta < cos T  (both angles in [0, 180] degrees).
  r.sign = sign_cos_difference(dot, squared_lengths_product, t);
  if (!with_margin) return r;
  Mpfr sine(192), cosine(192);
  mpfr_set_z(sine.v, cross.get_mpz_t(), MPFR_RNDN);
  mpfr_set_z(cosine.v, dot.get_mpz_t(), MPFR_RNDN);
  r.margin_text = margin_degrees(sine, cosine, t, r.sign);
  return r;
}

}  // namespace cutcom::ref
