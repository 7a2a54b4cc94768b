// TRC-LOOK-4 in fast: the choice of two intersections from the carriers (nearer_choice), against
// the points themselves, and the ties it must see as ties.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../fast/src/plane_geometry.hpp"

namespace cutcom::fast {
namespace {

Carrier line(Vec2 p, Vec2 d) { return {false, p, d, 0}; }
Carrier circle(Vec2 c, double radius) { return {true, c, {}, radius}; }

// covers: TRC-LOOK-4
TEST(NearerChoice, MarginIsHalfTheDifferenceOfSquaredDistancesOverTheChord) {
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> coordinate(-20, 20), radius(1, 30);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    Vec2 p{coordinate(random), coordinate(random)}, ahead{coordinate(random), coordinate(random)};
    Carrier a = circle({coordinate(random), coordinate(random)}, radius(random));
    Carrier others[] = {line({coordinate(random), coordinate(random)}, {coordinate(random), coordinate(random)}),
                        circle({coordinate(random), coordinate(random)}, radius(random))};
    for (const Carrier& b : others)
      for (auto [u, v] : {std::pair<const Carrier*, const Carrier*>{&a, &b}, {&b, &a}}) {
        Vec2 xs[2];
        if (carrier_intersections(*u, *v, xs) != 2) continue;
        double chord = norm(xs[1] - xs[0]);
        if (chord < 1e-3) continue;  // nearly touching: the points' own rounding dominates
        long double d0 = dot(xs[0] - p, xs[0] - p), d1 = dot(xs[1] - p, xs[1] - p);
        double expected = static_cast<double>((d1 - d0) / (2 * chord));
        NearerChoice c = nearer_choice(*u, *v, xs, p, ahead);
        EXPECT_NEAR(c.first_nearer, expected, 1e-9 * (1 + 40 * 40 / chord));
        if (std::fabs(expected) > 1e-6) {
          EXPECT_EQ(c.second, expected < 0);
        }
        Vec2 out;
        ASSERT_TRUE(nearest_intersection(*u, *v, p, ahead, out));
        Vec2 taken = xs[c.second ? 1 : 0];
        EXPECT_TRUE(out.a == taken.a && out.b == taken.b);
        ++compared;
      }
  }
  EXPECT_GT(compared, 1000);
}

// covers: TRC-LOOK-4
TEST(NearerChoice, APointOnTheAxisIsATieThatGoesFurtherAlong) {
  // Line y = 1 and the circle of radius 6 about (10.1,-4.5): points at x = 10.1 -+ sqrt(5.75),
  // seen from (10.1, 1.5) on the axis x = 10.1, and the points themselves.
  Carrier l = line({0, 1}, {1, 0}), c = circle({10.1, -4.5}, 6);
  Vec2 xs[2];
  ASSERT_EQ(carrier_intersections(l, c, xs), 2);
  for (Vec2 ahead : {Vec2{1, 0}, Vec2{-1, 0.5}}) {
    NearerChoice k = nearer_choice(l, c, xs, {10.1, 1.5}, ahead);
    EXPECT_EQ(k.first_nearer, 0);
    EXPECT_EQ(k.second, ahead.a > 0);  // the second point lies along +X
    Vec2 out, want = xs[ahead.a > 0 ? 1 : 0];
    NearerChoice taken;
    ASSERT_TRUE(nearest_intersection(l, c, {10.1, 1.5}, ahead, out, &taken));
    EXPECT_TRUE(out.a == want.a && out.b == want.b);
    EXPECT_EQ(taken.second, k.second);
  }
  // Two circles with centres on a line, the point on it (a rounding off it): equally near.
  Carrier a = circle({0.1, 0.3}, 5), b = circle({6.1, 0.3 + 8 * 0.1}, 4);
  ASSERT_EQ(carrier_intersections(a, b, xs), 2);
  Vec2 on_centres = a.point + 2.5 * (b.point - a.point);
  EXPECT_EQ(nearer_choice(a, b, xs, on_centres, {0, 1}).first_nearer, 0);
  // Off the axis by far more than fast's error: no tie.
  ASSERT_EQ(carrier_intersections(l, c, xs), 2);
  EXPECT_GT(std::fabs(nearer_choice(l, c, xs, {10.1 + 1e-9, 1.5}, {1, 0}).first_nearer), 0);
  // One point (tangent): a tie.
  Carrier tangent = circle({10.1, -5}, 6);
  Vec2 out;
  NearerChoice one{1, true};
  ASSERT_TRUE(nearest_intersection(l, tangent, {3, 4}, {1, 0}, out, &one));
  EXPECT_EQ(one.first_nearer, 0);
}

}  // namespace
}  // namespace cutcom::fast
