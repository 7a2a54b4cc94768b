#include "edge_strategy.hpp"

#include "circle_position.hpp"
#include "exact_root.hpp"
#include "filtered.hpp"

namespace cutcom::ref {

namespace {
bool on_curve(const EdgeCurve& c, const Point& p) {
  if (c.bound == EdgeCurve::Bound::kWhole) return true;
  FT t = (p - c.carrier.point) * c.carrier.direction;  // times |direction|^2
  if (CGAL::sign(t) == CGAL::NEGATIVE) return false;
  return c.bound == EdgeCurve::Bound::kRay || CGAL::compare(t, c.carrier.direction.squared_length()) != CGAL::LARGER;
}

// Signed position of p relative to q along element e's equidistant (> 0: p comes later).
CGAL::Sign compare_along(const ContourElement& e, const Point& p, const Point& q) {
  if (!e.is_arc()) return CGAL::sign((p - q) * e.d);
  CircleFrame f(q - e.centre, e.sense);
  return f.compare(f.signed_from(f.start(), p - e.centre), f.start());
}
}  // namespace

Carrier<Kernel> carrier_of(const ContourElement& e, const FT& radius, const FT& side_radius) {
  Carrier<Kernel> c;
  c.circle = e.is_arc();
  if (c.circle) {
    c.point = e.centre, c.radius = radius;
  } else {
    c.point = equidistant_point<Kernel>(e.a, e.normal, side_radius), c.direction = e.d;
  }
  return c;
}

// TRC-EDGE-2, TRC-EDGE-3, TRC-EDGE-4: G460 the straight line between the normal point and the programmed position
// off the contour; G461 the circle of radius r about the programmed end (start) point; G462 the
// tangent extension of the equidistant beyond its normal point. `normal_point`, `vertex` and
// `outward` (the tangent pointing away from the contour) belong to the too-short block.
EdgeCurve edge_curve(EdgeStrategy strategy, const Point& vertex, const Point& normal_point, const Vector& outward,
                     const Point& off_contour, bool approach, const FT& r) {
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

// TRC-EDGE-5: the points where the curve meets element e's equidistant between `from` (or its
// normal start) and its normal end; the first (retraction) or the last (approach) along it.
// The margin is the hit's least slack to the ends of the equidistant piece (along a line; the
// chord to a circle's end) and of the curve and, with a circle, the depth of the carriers'
// overlap; without a hit, the largest (negative) such value over the carriers' intersections.
EdgeHit edge_hit(const EdgeCurve& curve, const ContourElement& e, const FT& radius, const FT& side_radius,
                 const std::optional<PieceStart>& from, bool last) {
  EdgeHit out;
  if (curve.carrier.circle && CGAL::sign(curve.carrier.radius) == CGAL::ZERO) return out;
  if (!curve.carrier.circle && CGAL::sign(curve.carrier.direction.squared_length()) == CGAL::ZERO) return out;
  auto least = [](std::optional<FT>& m, const FT& v) {
    if (!m || margin_less(v, *m)) m = v;  // a margin, reported only: filtered
  };
  Carrier<Kernel> ce = carrier_of(e, radius, side_radius);
  std::optional<FT> depth;  // none: unbounded (two lines)
  if (curve.carrier.circle || e.is_arc()) depth = -carrier_gap<Kernel>(ce, curve.carrier);
  std::vector<Point> xs = carrier_intersections<Kernel>(ce, curve.carrier);
  if (xs.empty() && depth) out.margin = exact_mm(*depth);
  Point start = from ? from->point : equidistant_point<Kernel>(e.a, e.start_normal(), side_radius);
  Point end = equidistant_point<Kernel>(e.b, e.end_normal(), side_radius);
  std::optional<FT> best_margin, none_margin;
  CircleFrame frame(e.a - e.centre, e.sense);  // arcs: positions from the programmed start
  std::optional<CirclePosition> best_position;
  for (const Point& p : xs) {
    std::optional<FT> m = depth;
    if (!curve.carrier.circle) {
      FT length = exact_root(curve.carrier.direction.squared_length());
      FT t = (p - curve.carrier.point) * curve.carrier.direction / length;
      least(m, t);
      if (curve.bound == EdgeCurve::Bound::kSegment) least(m, length - t);
    }
    // Where p lies on the piece from `start` to the normal end: lines by length, circles by
    // the rotation in [0, 2 pi) from `start` in the circle's sense.
    bool on_piece;
    std::optional<CirclePosition> position;
    if (!e.is_arc()) {
      FT along = (p - start) * e.d / e.length, left = (end - p) * e.d / e.length;
      on_piece = CGAL::sign((p - start) * e.d) != CGAL::NEGATIVE && CGAL::sign((end - p) * e.d) != CGAL::NEGATIVE;
      least(m, along), least(m, left);
    } else {
      // What is left of the circle after `start`, as close_open measures it: the sweep less the
      // rotation already cut at the start; more than a turn after a G451 extension.
      CirclePosition first = from ? from->position : frame.start();
      position = frame.forward_from(first, p - e.centre);
      on_piece = frame.compare(frame.end(e.b - e.centre, e.full_circle), *position) != CGAL::NEGATIVE;
      FT to_start = exact_root(CGAL::squared_distance(p, start)), to_end = exact_root(CGAL::squared_distance(p, end));
      if (on_piece) {
        least(m, to_start), least(m, to_end);
      } else {  // outside: the nearer of the two ends
        least(m, -(margin_less(to_start, to_end) ? to_start : to_end));
      }
    }
    bool valid = on_curve(curve, p) && on_piece;
    if (!valid) {
      if (!none_margin || (m && margin_less(*none_margin, *m))) none_margin = m;
      continue;
    }
    bool better = !out.point;
    if (!better) {
      CGAL::Sign later = position ? frame.compare(*position, *best_position) : compare_along(e, p, *out.point);
      better = later == (last ? CGAL::POSITIVE : CGAL::NEGATIVE);
    }
    if (better) out.point = p, best_margin = m, best_position = position;
  }
  if (out.point)
    out.margin = best_margin ? exact_mm(*best_margin) : "inf";
  else if (none_margin)
    out.margin = exact_mm(*none_margin);
  return out;
}

}  // namespace cutcom::ref
