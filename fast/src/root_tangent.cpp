#include "root_tangent.hpp"

namespace cutcom::fast {

namespace {

__extension__ typedef unsigned __int128 U128;

void assign(mpz_class& z, Int128 v) {
  bool negative = v < 0;
  U128 m = negative ? U128(0) - static_cast<U128>(v) : static_cast<U128>(v);
  mpz_set_ui(z.get_mpz_t(), static_cast<unsigned long>(m >> 64));
  mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), 64);
  mpz_add_ui(z.get_mpz_t(), z.get_mpz_t(), static_cast<unsigned long>(m & ~0ul));
  if (negative) mpz_neg(z.get_mpz_t(), z.get_mpz_t());
}

// z = x0·y1 − x1·y0 (cross) or x0·y0 + x1·y1 (dot), in place.
void cross(mpz_class& z, const std::array<mpz_class, 2>& x, const std::array<mpz_class, 2>& y) {
  mpz_mul(z.get_mpz_t(), x[0].get_mpz_t(), y[1].get_mpz_t());
  mpz_submul(z.get_mpz_t(), x[1].get_mpz_t(), y[0].get_mpz_t());
}
void dot(mpz_class& z, const std::array<mpz_class, 2>& x, const std::array<mpz_class, 2>& y) {
  mpz_mul(z.get_mpz_t(), x[0].get_mpz_t(), y[0].get_mpz_t());
  mpz_addmul(z.get_mpz_t(), x[1].get_mpz_t(), y[1].get_mpz_t());
}

}  // namespace

int RootTangents::sign_of(const mpz_class& a, const mpz_class& b, const mpz_class& x) {
  int sa = sgn(a), sb = sgn(x) == 0 ? 0 : sgn(b);
  if (sb == 0) return sa;
  if (sa == 0 || sa == sb) return sb;
  mpz_mul(s_.get_mpz_t(), a.get_mpz_t(), a.get_mpz_t());  // opposite signs: compare a² with b²x
  mpz_mul(t_.get_mpz_t(), b.get_mpz_t(), b.get_mpz_t());
  mpz_mul(t_.get_mpz_t(), t_.get_mpz_t(), x.get_mpz_t());
  int c = mpz_cmp(s_.get_mpz_t(), t_.get_mpz_t());
  return sa * ((c > 0) - (c < 0));
}

// U + V√y with U = a + b√x, V = c + e√x: where U and V differ in sign, its sign is U's times that
// of U² − V²y = (a² + b²x − y(c² + e²x)) + 2(ab − yce)√x.
int RootTangents::sign_of(const mpz_class& a, const mpz_class& b, const mpz_class& c, const mpz_class& e,
                          const mpz_class& x, const mpz_class& y) {
  if (sgn(y) == 0) return sign_of(a, b, x);
  int su = sign_of(a, b, x), sv = sign_of(c, e, x);
  if (sv == 0) return su;
  if (su == 0 || su == sv) return sv;
  mpz_mul(u_.get_mpz_t(), a.get_mpz_t(), a.get_mpz_t());
  mpz_mul(s_.get_mpz_t(), b.get_mpz_t(), b.get_mpz_t());
  mpz_addmul(u_.get_mpz_t(), s_.get_mpz_t(), x.get_mpz_t());
  mpz_mul(t_.get_mpz_t(), e.get_mpz_t(), e.get_mpz_t());
  mpz_mul(t_.get_mpz_t(), t_.get_mpz_t(), x.get_mpz_t());
  mpz_addmul(t_.get_mpz_t(), c.get_mpz_t(), c.get_mpz_t());
  mpz_submul(u_.get_mpz_t(), t_.get_mpz_t(), y.get_mpz_t());
  mpz_mul(v_.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  mpz_mul(s_.get_mpz_t(), c.get_mpz_t(), e.get_mpz_t());
  mpz_submul(v_.get_mpz_t(), s_.get_mpz_t(), y.get_mpz_t());
  mpz_mul_2exp(v_.get_mpz_t(), v_.get_mpz_t(), 1);
  return su * sign_of(u_, v_, x);
}

bool RootTangents::tangent_of(const BlockCopy& c, PlaneAxes axes, bool at_end, Tangent& t) {
  if (!c.exact) return false;
  const auto ia = static_cast<std::size_t>(axes.abscissa), io = static_cast<std::size_t>(axes.ordinate);
  assign(d0_, c.delta[ia]), assign(d1_, c.delta[io]);
  t.q = 0, t.r[0] = 0, t.r[1] = 0;
  if (!c.arc) {  // a line: its displacement
    t.p[0] = d0_, t.p[1] = d1_;
    return true;
  }
  const long sigma = c.sense;
  mpz_mul(length2_.get_mpz_t(), d0_.get_mpz_t(), d0_.get_mpz_t());
  mpz_addmul(length2_.get_mpz_t(), d1_.get_mpz_t(), d1_.get_mpz_t());
  if (c.has_centre) {  // as exact_tangent.hpp, in GMP's integers
    assign(k0_, c.to_centre[ia]), assign(k1_, c.to_centre[io]);
    if (sgn(length2_) == 0) {  // a full circle: σ·perp(start − c)
      mpz_mul_si(t.p[0].get_mpz_t(), k1_.get_mpz_t(), sigma);
      mpz_mul_si(t.p[1].get_mpz_t(), k0_.get_mpz_t(), -sigma);
      return true;
    }
    mpz_mul(n_.get_mpz_t(), k1_.get_mpz_t(), d0_.get_mpz_t());  // n = (c − start)·perp d
    mpz_submul(n_.get_mpz_t(), k0_.get_mpz_t(), d1_.get_mpz_t());
    mpz_mul_2exp(n_.get_mpz_t(), n_.get_mpz_t(), 1);
    if (!at_end) mpz_neg(length2_.get_mpz_t(), length2_.get_mpz_t());
    mpz_mul(t.p[0].get_mpz_t(), n_.get_mpz_t(), d0_.get_mpz_t());  // σ(2n d ± L perp d)
    mpz_submul(t.p[0].get_mpz_t(), length2_.get_mpz_t(), d1_.get_mpz_t());
    mpz_mul(t.p[1].get_mpz_t(), n_.get_mpz_t(), d1_.get_mpz_t());
    mpz_addmul(t.p[1].get_mpz_t(), length2_.get_mpz_t(), d0_.get_mpz_t());
    mpz_mul_si(t.p[0].get_mpz_t(), t.p[0].get_mpz_t(), sigma);
    mpz_mul_si(t.p[1].get_mpz_t(), t.p[1].get_mpz_t(), sigma);
    return true;
  }
  if (sgn(length2_) == 0) return false;  // CR= with start = end: unreachable (ARC-CR-1), never here
  // ARC-CR-1: Q = L(4CR² − L), 0 for a chord a rounding longer than 2|CR| (a half circle).
  assign(n_, c.cr_units);
  mpz_mul(t.q.get_mpz_t(), n_.get_mpz_t(), n_.get_mpz_t());
  mpz_mul_2exp(t.q.get_mpz_t(), t.q.get_mpz_t(), 2);
  mpz_sub(t.q.get_mpz_t(), t.q.get_mpz_t(), length2_.get_mpz_t());
  if (sgn(t.q) < 0) t.q = 0;
  mpz_mul(t.q.get_mpz_t(), t.q.get_mpz_t(), length2_.get_mpz_t());
  const long k = (c.sense > 0) == (c.cr_units > 0) ? 1 : -1;   // the short arc for CR > 0
  mpz_mul_si(t.r[0].get_mpz_t(), d0_.get_mpz_t(), sigma * k);  // σk√Q d
  mpz_mul_si(t.r[1].get_mpz_t(), d1_.get_mpz_t(), sigma * k);
  const long across = at_end ? sigma : -sigma;  // ± σ L perp d, perp d = (−d1, d0)
  mpz_mul(t.p[0].get_mpz_t(), length2_.get_mpz_t(), d1_.get_mpz_t());
  mpz_mul_si(t.p[0].get_mpz_t(), t.p[0].get_mpz_t(), -across);
  mpz_mul(t.p[1].get_mpz_t(), length2_.get_mpz_t(), d0_.get_mpz_t());
  mpz_mul_si(t.p[1].get_mpz_t(), t.p[1].get_mpz_t(), across);
  return true;
}

std::optional<RootTangents::Signs> RootTangents::corner(const BlockCopy& first, const BlockCopy& second,
                                                        PlaneAxes axes) {
  if (!tangent_of(first, axes, true, first_) || !tangent_of(second, axes, false, second_)) return std::nullopt;
  // t1 = p1 + √x r1, t2 = p2 + √y r2: a product is p1∘p2 + √x r1∘p2 + √y p1∘r2 + √(xy) r1∘r2.
  Signs s;
  cross(a_, first_.p, second_.p), cross(b_, first_.r, second_.p), cross(c_, first_.p, second_.r);
  cross(e_, first_.r, second_.r);
  s.cross = sign_of(a_, b_, c_, e_, first_.q, second_.q);
  dot(a_, first_.p, second_.p), dot(b_, first_.r, second_.p), dot(c_, first_.p, second_.r);
  dot(e_, first_.r, second_.r);
  s.dot = sign_of(a_, b_, c_, e_, first_.q, second_.q);
  return s;
}

std::optional<int> RootTangents::side(const BlockCopy& block, bool at_end, PlaneAxes axes,
                                      const std::array<Int128, 3>& u) {
  if (!tangent_of(block, axes, at_end, first_)) return std::nullopt;
  std::array<mpz_class, 2>& v = second_.p;
  assign(v[0], u[static_cast<std::size_t>(axes.abscissa)]), assign(v[1], u[static_cast<std::size_t>(axes.ordinate)]);
  cross(a_, first_.p, v), cross(b_, first_.r, v);
  return sign_of(a_, b_, first_.q);
}

}  // namespace cutcom::fast
