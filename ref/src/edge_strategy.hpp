// G460 / G461 / G462 (TRC-EDGE-*): the auxiliary curves of the strategies and their intersection
// with a neighbour's equidistant, exact. The engine decides when a strategy applies; this file
// holds the geometry.
#pragma once

#include <optional>
#include <string>

#include "circle_position.hpp"
#include "contour_element.hpp"
#include "equidistant.hpp"

namespace cutcom::ref {

// The carrier of an element's equidistant (`radius`: the circle's equidistant radius).
Carrier<Kernel> carrier_of(const ContourElement& e, const FT& radius, const FT& side_radius);

// The auxiliary curve of a strategy, and how much of its carrier counts.
struct EdgeCurve {
  Carrier<Kernel> carrier;
  enum class Bound { kWhole, kRay, kSegment } bound = Bound::kWhole;
};

// TRC-EDGE-2, TRC-EDGE-3, TRC-EDGE-4: `vertex`, `normal_point` and `outward` (the tangent pointing
// away from the contour) belong to the too-short block; `off_contour` is the programmed position
// off the contour (retraction: the end; approach: the start); r is the tool radius.
EdgeCurve edge_curve(EdgeStrategy strategy, const Point& vertex, const Point& normal_point, const Vector& outward,
                     const Point& off_contour, bool approach, const FT& r);

// TRC-EDGE-5: the first (retraction) or last (approach) point where the curve meets e's
// equidistant between `from` (default: its normal start) and its normal end, with the margin text.
struct EdgeHit {
  std::optional<Point> point;
  std::string margin = "-inf";
};
// The start of the piece searched when it is not the normal start: its point and its position
// on e's circle from the programmed start (arcs; as the open element holds it).
struct PieceStart {
  Point point;
  CirclePosition position;
};
EdgeHit edge_hit(const EdgeCurve& curve, const ContourElement& e, const FT& radius, const FT& side_radius,
                 const std::optional<PieceStart>& from, bool last);

}  // namespace cutcom::ref
