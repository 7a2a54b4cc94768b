// TRC-ARC-CORNER-1, TRC-LOOK-2: of two intersections of carriers the one nearer the corner, and
// equally near the one further along the next block (Compensation::nearest_intersection). The
// signs second_farther and second_ahead take from the carriers without the square root must be
// those of the points themselves: random exact carriers with roots, and constructed ties.
#include <gtest/gtest.h>

#include <random>

#include "equidistant.hpp"
#include "kernel.hpp"

namespace cutcom::ref {
namespace {

using C = Carrier<Kernel>;

C line(const Point& p, const Vector& d) { return C{false, p, d, FT(0)}; }
C circle(const Point& c, const FT& radius) { return C{true, c, Vector(0, 0), radius}; }

// Both signs against the points; false where the carriers do not give two points.
bool check(const C& u, const C& v, const Point& p, const Vector& w) {
  std::vector<Point> xs = carrier_intersections<Kernel>(u, v);
  if (xs.size() != 2) return false;
  EXPECT_EQ(second_farther(u, v, p), CGAL::compare_distance_to_point(p, xs[1], xs[0]));
  EXPECT_EQ(second_ahead(u, v, w), CGAL::sign((xs[1] - xs[0]) * w));
  return true;
}

// TRC-LOOK-4's margin against the points: half the difference of the squared distances over the
// chord (to 1e-12 of the sizes: an exact comparison of these nested roots takes CORE minutes).
void check_first_nearer_by(const C& u, const C& v, const Point& p) {
  std::vector<Point> xs = carrier_intersections<Kernel>(u, v);
  ASSERT_EQ(xs.size(), 2u);
  FT chord = CGAL::sqrt(CGAL::squared_distance(xs[0], xs[1]));
  FT half_difference = (CGAL::squared_distance(p, xs[1]) - CGAL::squared_distance(p, xs[0])) / FT(2);
  EXPECT_NEAR(CGAL::to_double(first_nearer_by(u, v, p)), CGAL::to_double(half_difference / chord), 1e-9);
}

// covers: TRC-ARC-CORNER-1 TRC-LOOK-2 TRC-LOOK-4
TEST(IntersectionOrder, SignsWithoutTheRootAreThePoints) {
  std::mt19937_64 random(20261129);
  auto n = [&](int range) { return FT(static_cast<long>(random() % (2 * range + 1)) - range); };
  auto root = [&] { return CGAL::sqrt(FT(static_cast<long>(random() % 1000 + 1))); };
  int pairs = 0;
  for (int i = 0; i < 3000; ++i) {
    Point p(n(50) + root() / FT(7), n(50)), c(n(20), n(20) + root());
    Vector d(n(9), n(9) + root() / FT(3)), w(n(5), n(5));
    C l = line(Point(n(20), n(20)), d), a = circle(c, root() * FT(4) + FT(1)),
      b = circle(Point(n(20), n(20)), n(30) + FT(31));
    pairs += check(l, a, p, w) + check(a, l, p, w) + check(a, b, p, w) + check(b, a, p, w);
    if (i < 50 && carrier_intersections<Kernel>(l, a).size() == 2) check_first_nearer_by(l, a, p);
    if (i < 50 && carrier_intersections<Kernel>(b, a).size() == 2) check_first_nearer_by(b, a, p);
  }
  EXPECT_GT(pairs, 2000);  // the draws meet often enough to mean something
}

// covers: TRC-ARC-CORNER-1 TRC-LOOK-4
TEST(IntersectionOrder, EquallyNearPointsAreTold) {
  // The corner on the perpendicular from the centre (line and circle) or on the line of centres
  // (two circles): both intersections equally near, exactly; then `ahead` decides.
  FT s2 = CGAL::sqrt(FT(2));
  C l = line(Point(FT(-7), s2), Vector(FT(3), FT(0))), a = circle(Point(FT(1), FT(0)), FT(5));
  for (const Point& p : {Point(FT(1), FT(9) + s2), Point(FT(1), -s2)})
    for (const Vector& w : {Vector(1, 0), Vector(-1, 2), Vector(0, 1)}) {
      ASSERT_TRUE(check(l, a, p, w));
      EXPECT_EQ(second_farther(l, a, p), CGAL::ZERO);
      EXPECT_EQ(CGAL::sign(first_nearer_by(l, a, p)), CGAL::ZERO);  // TRC-LOOK-4: a tie
    }
  C b = circle(Point(FT(4), s2), FT(4));
  for (const Point& p : {Point(FT(-2), -s2), Point(FT(7), s2 * FT(2))})  // on the line of centres
    for (const Vector& w : {Vector(1, 0), Vector(0, -1), Vector(2, 3)}) {
      ASSERT_TRUE(check(a, b, p, w));
      ASSERT_TRUE(check(b, a, p, w));
      EXPECT_EQ(second_farther(a, b, p), CGAL::ZERO);
      EXPECT_EQ(CGAL::sign(first_nearer_by(b, a, p)), CGAL::ZERO);
    }
}

}  // namespace
}  // namespace cutcom::ref
