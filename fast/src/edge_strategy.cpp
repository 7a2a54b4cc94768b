#include "edge_strategy.hpp"

#include <algorithm>
#include <limits>
#include <numbers>

namespace cutcom::fast {

namespace {
// Position along an element's equidistant, relative to its normal start (lines: length; arcs:
// rotation in (-pi, pi]).
double along(const Element& e, Vec2 p, double side_radius) {
  if (!e.arc) return dot(p - Element::offset(e.start, e.unit, side_radius), e.unit);
  return signed_rotation(e.start - e.centre, p - e.centre, e.sense);
}
}  // namespace

Carrier carrier_of(const Element& e, double radius, double side_radius) {
  Carrier c;
  c.circle = e.arc;
  if (e.arc)
    c.point = e.centre, c.radius = radius;
  else
    c.point = Element::offset(e.start, e.unit, side_radius), c.direction = e.unit;
  return c;
}

// TRC-EDGE-2, TRC-EDGE-3, TRC-EDGE-4: the auxiliary curve of the strategy (see ref for the geometry).
EdgeCurve edge_curve(EdgeStrategy strategy, double r, Vec2 vertex, Vec2 normal_point, Vec2 outward, Vec2 off_contour,
                     bool approach) {
  EdgeCurve c;
  switch (strategy) {
    case EdgeStrategy::kG460:  // TRC-EDGE-2
      c.bound = EdgeCurve::Bound::kSegment;
      c.carrier.point = approach ? off_contour : normal_point;
      c.carrier.direction = approach ? normal_point - off_contour : off_contour - normal_point;
      break;
    case EdgeStrategy::kG461:  // TRC-EDGE-3
      c.carrier.circle = true, c.carrier.point = vertex, c.carrier.radius = r;
      break;
    case EdgeStrategy::kG462:  // TRC-EDGE-4
      c.bound = EdgeCurve::Bound::kRay;
      c.carrier.point = normal_point, c.carrier.direction = outward;
      break;
  }
  return c;
}

// TRC-EDGE-5: where the curve meets e's equidistant between `from` (or its normal start) and its
// normal end; the first (retraction) or last (approach) along it. `margin` as in ref: the hit's
// least slack to the bounds (and the carriers' overlap with a circle); without a hit the
// largest negative one.
bool edge_hit(const EdgeCurve& curve, const Element& e, double radius, double side_radius, const PieceStart* from,
              bool last, Vec2& out, double& margin) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  margin = -kInf;
  if (curve.carrier.circle ? !(curve.carrier.radius > 0) : dot(curve.carrier.direction, curve.carrier.direction) == 0)
    return false;
  Carrier ce = carrier_of(e, radius, side_radius);
  bool circle = curve.carrier.circle || e.arc;
  double depth = circle ? -carrier_gap(ce, curve.carrier) : kInf;
  Vec2 xs[2];
  int n = carrier_intersections(ce, curve.carrier, xs);
  if (n == 0 && circle) margin = std::min(depth, -std::numeric_limits<double>::denorm_min());
  bool found = false;
  double best = 0, best_margin = 0;
  // The carriers meet (n > 0): their overlap is at least 0, whatever the rounding of the gap.
  if (n > 0) depth = std::max(depth, 0.0);
  for (int i = 0; i < n; ++i) {
    // The point counts when every slack is at least 0 (the boundary rule: an end is on), so the
    // branch follows from the margin m itself.
    double m = depth;
    if (!curve.carrier.circle) {
      double length = norm(curve.carrier.direction);
      double t = dot(xs[i] - curve.carrier.point, curve.carrier.direction) / length;
      m = std::min(m, t);
      if (curve.bound == EdgeCurve::Bound::kSegment) m = std::min(m, length - t);
    }
    // Position on the piece from `from` (or the normal start) to the normal end: lines by
    // length, circles by the rotation in [0, 2 pi) from `from` (slack: the chord to each end).
    double a, lower_mm, upper_mm;
    if (!e.arc) {
      a = along(e, xs[i], side_radius);
      double lower = from ? along(e, from->point, side_radius) : 0.0;
      lower_mm = a - lower, upper_mm = e.length - a;
    } else {
      constexpr double kTurn = 2 * std::numbers::pi;
      Vec2 start = from ? from->point : Element::offset(e.start, e.start_tangent(), side_radius);
      Vec2 end = Element::offset(e.end, e.end_tangent(), side_radius);
      Vec2 f = start - e.centre;
      double t = signed_rotation(f, xs[i] - e.centre, e.sense);
      a = t < 0 ? t + kTurn : t;
      // What is left of the circle after `from`, as close_open measures it.
      double room = sweep(e) - (from ? from->rotation : 0.0);
      lower_mm = norm(xs[i] - start), upper_mm = norm(xs[i] - end);
      // Beyond the room by the rotation: off by the nearer end (a point that is an end is on).
      if (a > room && lower_mm != 0 && upper_mm != 0) lower_mm = upper_mm = -std::min(lower_mm, upper_mm);
    }
    m = std::min({m, lower_mm, upper_mm});
    if (!(m >= 0)) {
      margin = std::max(margin, m);
      continue;
    }
    if (!found || (last ? a > best : a < best)) found = true, best = a, out = xs[i], best_margin = m;
  }
  if (found) margin = best_margin;
  return found;
}

}  // namespace cutcom::fast
