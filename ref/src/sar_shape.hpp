// The SAR element in the plane, exactly (spec SAR-POINTS-1, SAR-POINTS-2): from P4, the tangent
// direction t at P4 and the side s, the point P3 where the straight line, quadrant or semicircle
// starts (approach) or ends (retraction). With u = t/|t| and n its left normal (one square root):
//   G147: P3 = P4 - L u            G148: P3 = P4 + L u
//   G247: C = P4 + s R n, P3 = C - R u      G248: C = P4 + s R n, P3 = C + R u
//   G347 / G348: C = P4 + s R n, P3 = P4 + 2 s R n
// Circles turn counter-clockwise for s = +1. The directions of travel at P3 and P4 are rational
// multiples of t and perp(t) for the circles (their corners are decided without roots); a
// straight element's direction is its displacement u L, as for every straight element in ref.
#pragma once

#include "contour_element.hpp"
#include "kernel.hpp"

namespace cutcom::ref {

struct SarShape {
  bool approach = true;
  bool circle = false;
  Point p3, p4;
  Vector start_dir, end_dir;  // of the element in its direction of travel
  FT size;                    // L (lines) or R (circles), units
  Point centre;
  int sense = 0;  // circles: +1 counter-clockwise, -1 clockwise
};

SarShape sar_shape(SarContour contour, const Point& p4, const Vector& t, int s, const FT& size);

// The element as a contour element of `block` (whose decimals give the applicates).
ContourElement sar_element(const SarShape& shape, const Block& block);

// A straight element between exact in-plane points (SAR leads, blocks after a SAR end point).
ContourElement exact_line(const Block& block, const Point& a, const Point& b);

}  // namespace cutcom::ref
