// G460 / G461 / G462 (TRC-EDGE-*) in double precision: the auxiliary curves and their
// intersection with a neighbour's equidistant. The engine decides when a strategy applies.
#pragma once

#include "cutcom/block.hpp"
#include "plane_geometry.hpp"

namespace cutcom::fast {

// The carrier of an element's equidistant (`radius`: a circle's equidistant radius; side_radius = s r).
Carrier carrier_of(const Element& e, double radius, double side_radius);

struct EdgeCurve {
  Carrier carrier;
  enum class Bound { kWhole, kRay, kSegment } bound = Bound::kWhole;
};

// TRC-EDGE-2, TRC-EDGE-3, TRC-EDGE-4 (see ref/src/edge_strategy.hpp for the arguments).
EdgeCurve edge_curve(EdgeStrategy strategy, double r, Vec2 vertex, Vec2 normal_point, Vec2 outward, Vec2 off_contour,
                     bool approach);

// TRC-EDGE-5: the first (retraction) or last (approach) hit on e's equidistant between `from`
// (default: its normal start) and its normal end; `margin` as ref reports it.
// The start of the piece searched when it is not the normal start: its point and its rotation
// from the normal start (arcs; as the open element holds it).
struct PieceStart {
  Vec2 point;
  double rotation = 0;
};
bool edge_hit(const EdgeCurve& curve, const Element& e, double radius, double side_radius, const PieceStart* from,
              bool last, Vec2& out, double& margin);

}  // namespace cutcom::fast
