// TRC-CD-3 in fast: the box around a circle piece, which lets the collision check pass over held
// pieces plainly apart from an entry. It must hold every point of the piece (else a crossing is
// missed) and should hold little more (else nothing is passed over).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "../fast/src/bottleneck.hpp"

namespace cutcom::fast {
namespace {

// The box of `n` points along the arc, and the most any point between two of them bulges out.
struct Sampled {
  PieceBox box;
  double bulge = 0;
};
Sampled sample(Vec2 centre, double radius, double start, double turn, int sense, int n) {
  Sampled s;
  s.box = {centre.a + radius * std::cos(start), centre.b + radius * std::sin(start), 0, 0, 0};
  s.box.hi_a = s.box.lo_a, s.box.hi_b = s.box.lo_b;
  for (int i = 0; i <= n; ++i) {
    double t = start + sense * turn * i / n;
    double a = centre.a + radius * std::cos(t), b = centre.b + radius * std::sin(t);
    s.box.lo_a = std::min(s.box.lo_a, a), s.box.hi_a = std::max(s.box.hi_a, a);
    s.box.lo_b = std::min(s.box.lo_b, b), s.box.hi_b = std::max(s.box.hi_b, b);
  }
  s.bulge = radius * (1 - std::cos(turn / n / 2));
  return s;
}

// covers: TRC-CD-3
TEST(PieceBox, ACirclePiecesBoxHoldsItsPointsAndOnlyTheExtremesItPasses) {
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> coordinate(-500, 500), radius(0.01, 200), angle(0, 2 * std::numbers::pi);
  for (int i = 0; i < 3000; ++i) {
    Vec2 c{coordinate(random), coordinate(random)};
    double rho = radius(random), start = angle(random), turn = angle(random);
    int sense = i % 2 == 0 ? 1 : -1;
    Vec2 a{c.a + rho * std::cos(start), c.b + rho * std::sin(start)};
    Vec2 b{c.a + rho * std::cos(start + sense * turn), c.b + rho * std::sin(start + sense * turn)};
    PieceBox box = PieceBox::of(PathPiece::circle(a, b, c, rho, sense));
    Sampled s = sample(c, rho, start, turn, sense, 4000);
    double slack = 1e-12 * (std::fabs(c.a) + std::fabs(c.b) + rho);
    // Holds every point: no bound inside the sampled box.
    ASSERT_LE(box.lo_a, s.box.lo_a + slack) << i;
    ASSERT_LE(box.lo_b, s.box.lo_b + slack) << i;
    ASSERT_GE(box.hi_a, s.box.hi_a - slack) << i;
    ASSERT_GE(box.hi_b, s.box.hi_b - slack) << i;
    // And no more: no bound beyond the points by more than the samples can miss.
    ASSERT_GE(box.lo_a, s.box.lo_a - s.bulge - slack) << i;
    ASSERT_GE(box.lo_b, s.box.lo_b - s.bulge - slack) << i;
    ASSERT_LE(box.hi_a, s.box.hi_a + s.bulge + slack) << i;
    ASSERT_LE(box.hi_b, s.box.hi_b + s.bulge + slack) << i;
  }
}

// covers: TRC-CD-3
TEST(PieceBox, QuarterArcsEndingOnExtremesAndWholeTurns) {
  const Vec2 c{10, -5};
  const double rho = 2;
  // Counterclockwise from +a to +b: the quarter's box, not the circle's.
  PieceBox q = PieceBox::of(PathPiece::circle({12, -5}, {10, -3}, c, rho, 1));
  EXPECT_EQ(q.lo_a, 10);
  EXPECT_EQ(q.hi_a, 12);
  EXPECT_EQ(q.lo_b, -5);
  EXPECT_EQ(q.hi_b, -3);
  // The same ends clockwise: three quarters, all but the quarter between them.
  PieceBox three = PieceBox::of(PathPiece::circle({12, -5}, {10, -3}, c, rho, -1));
  EXPECT_EQ(three.lo_a, 8);
  EXPECT_EQ(three.hi_a, 12);
  EXPECT_EQ(three.lo_b, -7);
  EXPECT_EQ(three.hi_b, -3);
  // A whole turn from a point back to it is the circle's box; without the turn, the point's.
  PieceBox whole =
      PieceBox::of(PathPiece::circle({11, -5 + std::sqrt(3.0)}, {11, -5 + std::sqrt(3.0)}, c, rho, 1, true));
  EXPECT_EQ(whole.lo_a, 8);
  EXPECT_EQ(whole.hi_b, -3);
  PieceBox point = PieceBox::of(PathPiece::circle({11, -3}, {11, -3}, c, rho, 1));
  EXPECT_EQ(point.lo_a, 11);
  EXPECT_EQ(point.hi_a, 11);
  // All but a sliver of the circle, its ends a rounding apart: the circle's box less nothing
  // (from the ends alone it would be a point).
  const double sliver = 1e-13;
  Vec2 from{c.a + rho * std::cos(0.3), c.b + rho * std::sin(0.3)};
  Vec2 to{c.a + rho * std::cos(0.3 - sliver), c.b + rho * std::sin(0.3 - sliver)};
  PieceBox nearly = PieceBox::of(PathPiece::circle(from, to, c, rho, 1));
  EXPECT_EQ(nearly.lo_a, 8);
  EXPECT_EQ(nearly.hi_a, 12);
  EXPECT_EQ(nearly.lo_b, -7);
  EXPECT_EQ(nearly.hi_b, -3);
  // Boxes apart by more than the pad are apart; a circle piece's own box is never apart from it.
  EXPECT_TRUE(PieceBox::apart(q, PieceBox::of(PathPiece::segment({12.1, -4}, {13, -4}))));
  EXPECT_FALSE(PieceBox::apart(three, PieceBox::of(PathPiece::segment({11.9, -4}, {13, -4}))));
}

}  // namespace
}  // namespace cutcom::fast
