#include "plane_geometry.hpp"

namespace cutcom::fast {

Corner classify_corner(const LineSegment& first, const LineSegment& second, int side, double radius) {
  Corner c;
  double sn = cross(first.unit, second.unit);
  double cs = dot(first.unit, second.unit);
  c.sine = side * sn;
  c.cosine = cs;
  if (sn == 0) {
    c.kind = cs > 0 ? Corner::Kind::kTangent : Corner::Kind::kReversal;
    c.trim = 0;
    return c;
  }
  c.kind = c.sine > 0 ? Corner::Kind::kInner : Corner::Kind::kOuter;
  // trim = s r tan(phi/2) with the sign of the turn; tan(phi/2) = sin/(1+cos) = (1-cos)/sin,
  // the form without cancellation chosen by the sign of cos.
  double tan_half = cs >= 0 ? sn / (1 + cs) : (1 - cs) / sn;
  c.trim = side * radius * tan_half;
  return c;
}

}  // namespace cutcom::fast
