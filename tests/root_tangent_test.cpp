// fast's signs of sums of square roots (fast/src/root_tangent.hpp): against integers where the
// roots are whole, against 4,096-bit MPFR elsewhere, and a CR= circle's tangent against its
// centre.
#include "../fast/src/root_tangent.hpp"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <random>

namespace cutcom::fast {
namespace {

class Random {
 public:
  explicit Random(unsigned long seed) : g_(seed) {}
  mpz_class integer(int bits, bool non_negative = false) {
    mpz_class v = 0;
    for (int b = 0; b < bits; b += 32) v = (v << 32) + static_cast<unsigned long>(g_() & 0xffffffffu);
    v >>= (bits + 31) / 32 * 32 - bits;
    return non_negative || g_() % 2 ? v : mpz_class(-v);
  }
  unsigned long next() { return g_(); }

 private:
  std::mt19937_64 g_;
};

// sign(a + b√x + c√y + e√(xy)) in 4,096 bits; 2 where the value is too near 0 to tell.
int mpfr_sign(const mpz_class& a, const mpz_class& b, const mpz_class& c, const mpz_class& e, const mpz_class& x,
              const mpz_class& y) {
  mpfr_t sum, term, rx, ry;
  for (mpfr_ptr p : {sum, term, rx, ry}) mpfr_init2(p, 4096);
  mpfr_set_z(rx, x.get_mpz_t(), MPFR_RNDN), mpfr_sqrt(rx, rx, MPFR_RNDN);
  mpfr_set_z(ry, y.get_mpz_t(), MPFR_RNDN), mpfr_sqrt(ry, ry, MPFR_RNDN);
  mpfr_set_z(sum, a.get_mpz_t(), MPFR_RNDN);
  mpfr_mul_z(term, rx, b.get_mpz_t(), MPFR_RNDN), mpfr_add(sum, sum, term, MPFR_RNDN);
  mpfr_mul_z(term, ry, c.get_mpz_t(), MPFR_RNDN), mpfr_add(sum, sum, term, MPFR_RNDN);
  mpfr_mul(term, rx, ry, MPFR_RNDN), mpfr_mul_z(term, term, e.get_mpz_t(), MPFR_RNDN);
  mpfr_add(sum, sum, term, MPFR_RNDN);
  int s = mpfr_zero_p(sum) || mpfr_get_exp(sum) < -3000 ? 2 : mpfr_sgn(sum);
  for (mpfr_ptr p : {sum, term, rx, ry}) mpfr_clear(p);
  return s;
}

// covers: TRC-CORNER-1
TEST(RootTangent, SignOfASumOfRootsIsExactWhereTheRootsAreWhole) {
  Random g(20261129);
  RootTangents roots;
  for (int k = 0; k < 20000; ++k) {
    int bits = 1 + static_cast<int>(g.next() % 200);
    mpz_class m = g.integer(bits, true), n = g.integer(bits, true);  // x = m², y = n²
    mpz_class a = g.integer(2 * bits), b = g.integer(bits), c = g.integer(bits), e = g.integer(bits / 2 + 1);
    if (k % 3 == 0) a = -(b * m + c * n + e * m * n);  // exactly 0
    if (k % 6 == 0) a += g.next() % 2 ? 1 : -1;        // one off it
    mpz_class value = a + b * m + c * n + e * m * n;
    ASSERT_EQ(roots.sign_of(a, b, c, e, m * m, n * n), sgn(value)) << k;
    ASSERT_EQ(roots.sign_of(value, 0, 0, 0, m * m, n * n), sgn(value)) << k;
    mpz_class two_terms = a + b * m;
    ASSERT_EQ(roots.sign_of(a, b, m * m), sgn(two_terms)) << k;
  }
}

// covers: TRC-CORNER-1
TEST(RootTangent, SignOfASumOfRootsAgreesWithManyBitsElsewhere) {
  Random g(1129);
  RootTangents roots;
  int decided = 0;
  for (int k = 0; k < 20000; ++k) {
    int bits = 1 + static_cast<int>(g.next() % 160);
    mpz_class x = g.integer(2 * bits, true), y = g.integer(2 * bits, true);
    mpz_class a = g.integer(2 * bits), b = g.integer(bits), c = g.integer(bits), e = g.integer(bits / 2 + 1);
    if (k % 2 == 0) {  // a near the other terms' sum: the signs are decided by the squaring
      mpfr_t t;
      mpfr_init2(t, 4096);
      mpfr_set_z(t, x.get_mpz_t(), MPFR_RNDN), mpfr_sqrt(t, t, MPFR_RNDN), mpfr_mul_z(t, t, b.get_mpz_t(), MPFR_RNDN);
      mpz_class s;
      mpfr_get_z(s.get_mpz_t(), t, MPFR_RNDN);
      mpfr_clear(t);
      a = -s;
      c = 0, e = 0;
    }
    int expected = mpfr_sign(a, b, c, e, x, y);
    if (expected == 2) continue;
    ++decided;
    ASSERT_EQ(roots.sign_of(a, b, c, e, x, y), expected) << k;
  }
  EXPECT_GT(decided, 19000);
}

// covers: TRC-CORNER-1 ARC-CR-1
TEST(RootTangent, ACrCircleIsTangentWhereItsCentreSaysSo) {
  // A line along (3, 4) into a ccw CR=5 circle from (3, 4) to (4, 7) about (−1, 7): tangent. The
  // same circle clockwise with CR=−5 is the long way round about the same centre: a reversal.
  BlockCopy line, arc;
  line.delta = {3'000'000'000, 4'000'000'000, 0};
  arc.arc = true, arc.sense = 1, arc.cr_units = 5'000'000'000;
  arc.delta = {1'000'000'000, 3'000'000'000, 0};
  PlaneAxes xy{0, 1, 2};
  RootTangents roots;
  auto signs = roots.corner(line, arc, xy);
  ASSERT_TRUE(signs);
  EXPECT_EQ(signs->cross, 0);
  EXPECT_EQ(signs->dot, 1);
  arc.sense = -1, arc.cr_units = -5'000'000'000;
  signs = roots.corner(line, arc, xy);
  EXPECT_EQ(signs->cross, 0);
  EXPECT_EQ(signs->dot, -1);
  arc.cr_units = 5'000'000'000;  // clockwise the short way, about (8, 4): it starts along +Y
  EXPECT_EQ(roots.corner(line, arc, xy)->cross, 1);
  // At its end (4, 7) the ccw circle runs along (0, 1); a line along (−1, 1000) turns left of it.
  arc.sense = 1;
  line.delta = {-1, 1000, 0};
  EXPECT_EQ(roots.corner(arc, line, xy)->cross, 1);
  line.delta = {0, 1, 0};
  EXPECT_EQ(roots.corner(arc, line, xy)->cross, 0);
  // KONT's side, t × u with t the circle's start tangent ∥ (3, 4): (1, 1) lies right of it.
  EXPECT_EQ(roots.side(arc, false, xy, {1, 1, 0}), -1);
  EXPECT_EQ(roots.side(arc, false, xy, {6, 8, 0}), 0);
  arc.exact = false;  // a SAR block's points are not its decimals
  EXPECT_FALSE(roots.corner(arc, line, xy));
}

}  // namespace
}  // namespace cutcom::fast
