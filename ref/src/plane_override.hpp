// What ref's SAR expansion hands the compensation beside a block: where the block's in-plane
// points are not its decimals (SAR-SUB-1, SAR-END-3), their exact values; and the block's exact
// points and element with them (as fast/src/block_copy.hpp; no code is shared).
#pragma once

#include <optional>

#include "contour_element.hpp"
#include "exact_path.hpp"
#include "sar_shape.hpp"

namespace cutcom::ref::detail {

struct PlaneOverride {
  std::optional<Point> start, end;
  std::optional<SarShape> shape;  // the SAR element
};

// The block's start (end): its decimals, or the override's exact in-plane point at the block's
// programmed applicate.
inline ExactPoint start_with(const Block& b, const PlaneOverride* o) {
  if (!o || !o->start) return ExactPoint::programmed(b.start);
  PlaneAxes axes = plane_axes(b.state.plane);
  return ExactPoint::in_plane(*o->start, coord(b.start, axes.applicate), axes);
}
inline ExactPoint end_with(const Block& b, const PlaneOverride* o) {
  if (!o || !o->end) return ExactPoint::programmed(b.end);
  PlaneAxes axes = plane_axes(b.state.plane);
  return ExactPoint::in_plane(*o->end, coord(b.end, axes.applicate), axes);
}

// The block's element in the plane `axes`: the SAR element, a straight element between the
// override's points, or the block as programmed.
inline ContourElement element_with(const Block& b, const PlaneOverride* o, PlaneAxes axes) {
  if (!o) return b.is_arc() ? ContourElement::of_arc(b, axes) : ContourElement::of_line(b, axes);
  if (o->shape) return sar_element(*o->shape, b);
  return exact_line(b, start_with(b, o).plane(axes), end_with(b, o).plane(axes));
}

}  // namespace cutcom::ref::detail
