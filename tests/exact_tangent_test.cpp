// fast's exact corner products (fast/src/exact_tangent.hpp) against GMP's integers.
#include "../fast/src/exact_tangent.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

#include "cutcom/units_mpz.hpp"

namespace cutcom::fast {
namespace {

// covers: TRC-CORNER-1
TEST(ExactTangent, SignOfADifferenceOfProductsIsExactIn256Bits) {
  std::mt19937_64 g(20261128);
  auto value = [&](int bits) {
    Int128 v = (static_cast<Int128>(g()) << 64 | g()) & ((Int128(1) << bits) - 1);
    return g() % 2 ? -v : v;
  };
  for (int k = 0; k < 200000; ++k) {
    int bits = 1 + static_cast<int>(g() % 126);
    Int128 p = value(bits), q = value(bits), r = value(bits), t = value(bits);
    if (k % 3 == 0) r = q, t = p;           // equal products: the tie
    if (k % 5 == 0) t += g() % 2 ? 1 : -1;  // (with the tie above: a product one factor off it)
    mpz_class d = to_mpz(p) * to_mpz(q) - to_mpz(r) * to_mpz(t);
    ASSERT_EQ(sign_of_difference(p, q, r, t), sgn(d)) << k;
  }
}

// covers: TRC-CORNER-1
TEST(ExactTangent, ATangentIsTheRadiusTurnedAQuarterInTheSenseOfTravel) {
  BlockCopy arc;
  arc.arc = true, arc.has_centre = true, arc.sense = 1;  // ccw from (10,0) to (0,10) about (0,0)
  arc.delta = {-10, 10, 0}, arc.to_centre = {-10, 0, 0};
  PlaneAxes xy{0, 1, 2};
  auto s = exact_tangent(arc, xy, false), e = exact_tangent(arc, xy, true);
  ASSERT_TRUE(s && e);
  EXPECT_TRUE(s->a == 0 && s->b > 0);  // +Y at the start
  EXPECT_TRUE(e->a < 0 && e->b == 0);  // -X at the end
  arc.sense = -1;                      // the same points clockwise (the long way): reversed
  s = exact_tangent(arc, xy, false);
  EXPECT_TRUE(s->a == 0 && s->b < 0);
  arc.has_centre = false;  // CR=: not exact
  EXPECT_FALSE(exact_tangent(arc, xy, false));
  arc.has_centre = true, arc.to_centre = {Int128(1) << 41, 0, 0};  // beyond 2^40 units
  EXPECT_FALSE(exact_tangent(arc, xy, false));
  BlockCopy line;
  line.delta = {3, 4, 0};
  EXPECT_TRUE(exact_tangent(line, xy, true)->a == 3);
  line.exact = false;  // a SAR block's points are not its decimals
  EXPECT_FALSE(exact_tangent(line, xy, true));
}

// covers: TRC-CORNER-1
TEST(ExactTangent, TwoLinesSignsAreExactBelowTwoToThe62AndDeclinedFromIt) {
  std::mt19937_64 g(20261202);
  PlaneAxes xy{0, 1, 2};
  CornerSignsMemo memo;
  BlockCopy first, second;
  for (int k = 0; k < 200000; ++k) {
    int bits = 1 + static_cast<int>(g() % 66);  // up to 2^66: the range's edge and past it
    auto value = [&] {
      Int128 v = static_cast<Int128>(g() & ((std::uint64_t{1} << std::min(bits, 63)) - 1));
      if (bits > 63) v <<= bits - 63;
      return g() % 2 ? -v : v;
    };
    first.delta = {value(), value(), 0};
    second.delta = k % 3 == 0 ? first.delta : std::array<Int128, 3>{value(), value(), 0};
    if (k % 5 == 0) second.delta[1] += g() % 2 ? 1 : -1;                   // one unit off collinear
    if (k % 7 == 0) second.delta = {-first.delta[0], -first.delta[1], 0};  // a reversal
    first.block = 2 * k, second.block = 2 * k + 1;                         // new blocks: the memo must not answer
    int cross = 9, dot = 9;
    bool found = memo.signs(first, second, xy, cross, dot);
    auto below = [](Int128 v) { return v < (Int128(1) << 62) && v > -(Int128(1) << 62); };
    bool exact = below(first.delta[0]) && below(first.delta[1]) && below(second.delta[0]) && below(second.delta[1]);
    ASSERT_EQ(found, exact) << k;  // as exact_tangent: a line from 2^62 units on is not taken
    if (!exact) continue;
    mpz_class a1 = to_mpz(first.delta[0]), b1 = to_mpz(first.delta[1]);
    mpz_class a2 = to_mpz(second.delta[0]), b2 = to_mpz(second.delta[1]);
    ASSERT_EQ(cross, sgn(mpz_class(a1 * b2 - b1 * a2))) << k;
    ASSERT_EQ(dot, sgn(mpz_class(a1 * a2 + b1 * b2))) << k;
  }
}

}  // namespace
}  // namespace cutcom::fast
