// exact_root.hpp's settle_filter and kernel.hpp's tighten_filters: where CORE's floating-point
// filter cannot tell an expression's sign (large coordinates cancelling), the filter is replaced by
// the value's nearest double with a bound of two ulps. The new filter must be sound (the exact
// value within its bound), decide the signs built on it again, and claim nothing where the nearest
// double is not a normal one.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kernel.hpp"

namespace cutcom::ref {
namespace {

// (X + a)^2 - X^2 - 2 X a - a^2 + v, exactly v, with X large enough that the filter's bound
// (its largest magnitude, about X^2, times 2^-53) swamps v: the sign is CORE's exact one.
FT hidden(const FT& v) {
  FT big(1'000'000'000'000'000L), a(7);
  return (big + a) * (big + a) - big * big - FT(2) * big * a - a * a + v;
}

// |fpVal - v| <= maxAbs * ind * 2^-53 and |v| <= maxAbs, decided exactly on the filter's numbers.
bool bound_holds(const FT& v) {
  const CORE::filteredFp& f = v.Rep()->ffVal;
  double value = f.getValue();
  // filteredFp keeps maxAbs and ind private; isOK() and the value are what CORE reads, so the
  // bound is the one settle_filter writes: 2 |d| with ind 2.
  FT bound = FT(2 * std::fabs(value)) * FT(2) * FT(std::ldexp(1.0, -53));
  return CGAL::compare(CGAL::abs(FT(value) - v), bound) != CGAL::LARGER &&
         CGAL::compare(CGAL::abs(v), FT(2 * std::fabs(value))) != CGAL::LARGER;
}

TEST(SettledFilter, DecidesAgainWhereTheCoordinatesHidTheSign) {
  FT third = hidden(FT(1)) / FT(3);  // exactly 1/3
  ASSERT_FALSE(third.Rep()->ffVal.isOK());
  FT root = exact_root(third);  // settles `third`
  EXPECT_TRUE(third.Rep()->ffVal.isOK());
  EXPECT_EQ(third.Rep()->ffVal.getValue(), nearest_double(third));
  EXPECT_TRUE(bound_holds(third));
  // Signs built on it are the filter's again, and right: sqrt(1/3) - 0.577 > 0, 0.578 - it > 0.
  FT above = root - FT(0.577), below = FT(0.578) - root;
  EXPECT_TRUE(above.Rep()->ffVal.isOK());
  EXPECT_TRUE(below.Rep()->ffVal.isOK());
  EXPECT_EQ(CGAL::sign(above), CGAL::POSITIVE);
  EXPECT_EQ(CGAL::sign(below), CGAL::POSITIVE);
}

TEST(SettledFilter, KeepsTheExactSignOfANegativeDivisor) {
  FT d = hidden(FT(-5)) / FT(7);  // exactly -5/7
  ASSERT_FALSE(d.Rep()->ffVal.isOK());
  const FT& settled = settled_divisor(d);
  EXPECT_TRUE(settled.Rep()->ffVal.isOK());
  EXPECT_LT(settled.Rep()->ffVal.getValue(), 0);
  EXPECT_TRUE(bound_holds(settled));
  FT sum = FT(1) / settled + FT(1.3);  // -7/5 + 1.3: the filter's again
  EXPECT_TRUE(sum.Rep()->ffVal.isOK());
  EXPECT_EQ(CGAL::sign(sum), CGAL::NEGATIVE);
}

TEST(SettledFilter, ClaimsNothingWhereTheNearestDoubleIsNotNormal) {
  FT tiny = FT(std::numeric_limits<double>::denorm_min()) / FT(4);  // below every double
  FT v = hidden(tiny);
  ASSERT_FALSE(v.Rep()->ffVal.isOK());
  FT root = exact_root(v);
  EXPECT_FALSE(v.Rep()->ffVal.isOK());  // an unbounded error: every later sign is exact
  EXPECT_EQ(CGAL::sign(root), CGAL::POSITIVE);
  EXPECT_EQ(CGAL::sign(root * root - tiny), CGAL::ZERO);
}

// A corner's point (compensation.cpp's nearest_intersection) far from the origin: 10^15 units
// plus 200 times a value whose filter cannot even tell its sign (exactly 1).
TEST(SettledFilter, ATightenedPointDecidesTheSignsBuiltOnIt) {
  FT big(1'000'000'000'000'000L);
  FT one = hidden(FT(3)) / FT(3);
  Point p(big + FT(200) * one, FT(-200) * one);
  FT before = p.x() - big - FT(100);
  ASSERT_FALSE(before.Rep()->ffVal.isOK());
  tighten_filters(p);
  EXPECT_TRUE(bound_holds(p.x()));
  EXPECT_EQ(p.y().Rep()->ffVal.getValue(), -200.0);
  FT after = p.x() - big - FT(100);  // built anew on the tightened coordinate
  EXPECT_TRUE(after.Rep()->ffVal.isOK());
  EXPECT_EQ(CGAL::sign(after), CGAL::POSITIVE);
  // A coordinate exactly 0 has no normal nearest double: its filter stays, its sign exact.
  Point q(hidden(FT(0)), big);
  tighten_filters(q);
  EXPECT_FALSE(q.x().Rep()->ffVal.isOK());
  EXPECT_EQ(CGAL::sign(q.x()), CGAL::ZERO);
}

}  // namespace
}  // namespace cutcom::ref
