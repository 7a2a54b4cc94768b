// TRC-CD-3 without margins (ref/src/piece_box.hpp): the certified bounds of the floating-point
// filter hold every exact value strictly inside, at unit scale and at the 10^12 units of a metre
// programmed in 10^-9 mm, for roots and nested expressions; a box holds each point of its piece;
// boxes apart mean no point of one piece lies in the other's box.
#include <gtest/gtest.h>

#include <random>

#include "bottleneck.hpp"
#include "filtered.hpp"
#include "piece_box.hpp"

namespace cutcom::ref {
namespace {

// lo < x < hi, decided exactly.
void expect_inside(const FT& x, const CertifiedBounds& b) {
  EXPECT_EQ(CGAL::compare(FT(b.lo), x), CGAL::SMALLER);
  EXPECT_EQ(CGAL::compare(x, FT(b.hi)), CGAL::SMALLER);
}

// covers: TRC-CD-3 PROP-TRACE-1
TEST(PieceBox, CertifiedBoundsHoldTheExactValue) {
  std::mt19937_64 random(20261130);
  auto n = [&](long range) { return FT(static_cast<long>(random() % (2 * range + 1)) - range); };
  auto root = [&] { return CGAL::sqrt(FT(static_cast<long>(random() % 100000 + 1))); };
  int bounded = 0;
  for (int i = 0; i < 2000; ++i) {
    FT scale = i % 2 ? FT(1) : FT(1'000'000'000'000L);
    FT values[] = {n(1000) * scale, root() * scale, (n(50) + root() / FT(7)) * scale / (root() + FT(1)),
                   CGAL::sqrt(root() * scale + FT(3)) - n(9), root() - root(), FT(0)};
    for (const FT& x : values)
      if (std::optional<CertifiedBounds> b = certified_bounds(x)) expect_inside(x, *b), ++bounded;
  }
  EXPECT_GT(bounded, 10000);  // the filter is sure almost always
}

// covers: TRC-CD-3
TEST(PieceBox, HoldsItsPieceAndApartMeansNoCommonPoint) {
  std::mt19937_64 random(20261131);
  auto n = [&](long range) { return FT(static_cast<long>(random() % (2 * range + 1)) - range); };
  auto root = [&] { return CGAL::sqrt(FT(static_cast<long>(random() % 1000 + 1))); };
  int apart = 0, close = 0;
  for (int i = 0; i < 1000; ++i) {
    Point a(n(100) + root(), n(100)), b(n(100), n(100) - root() / FT(3)), c(n(100), n(100) + root());
    FT radius = root() + FT(1);
    PathPiece segment = PathPiece::segment(a, b), circle = PathPiece::circle(a, a, c, radius, 1, true);
    std::optional<PieceBox> s = PieceBox::of(segment), k = PieceBox::of(circle);
    ASSERT_TRUE(s && k);
    auto inside = [](const PieceBox& box, const Point& p) {
      return CGAL::compare(FT(box.lo[0]), p.x()) == CGAL::SMALLER &&
             CGAL::compare(p.x(), FT(box.hi[0])) == CGAL::SMALLER &&
             CGAL::compare(FT(box.lo[1]), p.y()) == CGAL::SMALLER &&
             CGAL::compare(p.y(), FT(box.hi[1])) == CGAL::SMALLER;
    };
    EXPECT_TRUE(inside(*s, a) && inside(*s, b));
    // The circle's extreme points.
    for (const Vector& v : {Vector(radius, 0), Vector(-radius, 0), Vector(0, radius), Vector(0, -radius)})
      EXPECT_TRUE(inside(*k, c + v));
    if (PieceBox::apart(*s, *k)) {
      ++apart;
      // No common point: the segment's carrier meets the circle nowhere on the segment.
      for (const Point& x : carrier_intersections<Kernel>(segment.carrier(), circle.carrier()))
        EXPECT_FALSE(inside(*s, x) && inside(*k, x));
    } else {
      ++close;
    }
  }
  EXPECT_GT(apart, 100);
  EXPECT_GT(close, 100);
}

}  // namespace
}  // namespace cutcom::ref
