// fast's SAR element in the plane (spec SAR-POINTS-1, SAR-POINTS-2), in double: from P4, the
// unit tangent u at P4 and the side s, the point P3 and the circle of the element.
#pragma once

#include "cutcom/block.hpp"
#include "plane_geometry.hpp"

namespace cutcom::fast {

struct SarShape {
  bool approach = true;
  bool circle = false;
  Vec2 p3, p4, centre;
  Vec2 end_unit;  // direction of travel where the element ends (unit)
  double size = 0;
  int sense = 0;
};

inline SarShape sar_shape(SarContour contour, Vec2 p4, Vec2 u, int s, double size) {
  SarShape sh;
  sh.p4 = p4, sh.size = size;
  Vec2 n = left_normal(u);
  sh.circle = contour != SarContour::kG147 && contour != SarContour::kG148;
  sh.approach = contour == SarContour::kG147 || contour == SarContour::kG247 || contour == SarContour::kG347;
  if (sh.circle) sh.centre = p4 + (s * size) * n, sh.sense = s;
  switch (contour) {
    case SarContour::kG147:
      sh.p3 = p4 - size * u, sh.end_unit = u;
      break;
    case SarContour::kG148:
      sh.p3 = p4 + size * u, sh.end_unit = u;
      break;
    case SarContour::kG247:
      sh.p3 = sh.centre - size * u, sh.end_unit = u;
      break;
    case SarContour::kG248:
      sh.p3 = sh.centre + size * u, sh.end_unit = static_cast<double>(s) * n;
      break;
    case SarContour::kG347:
      sh.p3 = p4 + (2 * s * size) * n, sh.end_unit = u;
      break;
    case SarContour::kG348:
      sh.p3 = p4 + (2 * s * size) * n, sh.end_unit = -1.0 * u;
      break;
  }
  return sh;
}

}  // namespace cutcom::fast
