#include "sar_shape.hpp"

#include "exact_root.hpp"

namespace cutcom::ref {

SarShape sar_shape(SarContour contour, const Point& p4, const Vector& t, int s, const FT& size) {
  SarShape sh;
  sh.p4 = p4, sh.size = size;
  FT length = exact_root(t.squared_length());
  Vector u = t / length, n(-u.y(), u.x());
  Vector perp(-t.y(), t.x());  // rational direction of n
  switch (contour) {
    // Lines: the direction is the displacement itself, u L (ref's straight elements keep d as
    // their tangent so that the corner trim can use |d|); the tangency at P4 is then an exact
    // zero test of cross(u L, t).
    case SarContour::kG147:  // SAR-POINTS-1
      sh.p3 = p4 - u * size, sh.start_dir = sh.end_dir = u * size;
      break;
    case SarContour::kG148:  // SAR-POINTS-2
      sh.approach = false, sh.p3 = p4 + u * size, sh.start_dir = sh.end_dir = u * size;
      break;
    case SarContour::kG247:
      sh.centre = p4 + n * (FT(s) * size), sh.p3 = sh.centre - u * size;
      sh.start_dir = perp * FT(-s), sh.end_dir = t;
      break;
    case SarContour::kG248:
      sh.approach = false, sh.centre = p4 + n * (FT(s) * size), sh.p3 = sh.centre + u * size;
      sh.start_dir = t, sh.end_dir = perp * FT(s);
      break;
    case SarContour::kG347:
      sh.centre = p4 + n * (FT(s) * size), sh.p3 = p4 + n * (FT(2 * s) * size);
      sh.start_dir = -t, sh.end_dir = t;
      break;
    case SarContour::kG348:
      sh.approach = false, sh.centre = p4 + n * (FT(s) * size), sh.p3 = p4 + n * (FT(2 * s) * size);
      sh.start_dir = t, sh.end_dir = -t;
      break;
  }
  sh.circle = contour != SarContour::kG147 && contour != SarContour::kG148;
  if (sh.circle) sh.sense = s;
  return sh;
}

ContourElement sar_element(const SarShape& sh, const Block& block) {
  ContourElement e;
  e.line = block.words.line;
  e.number = block.words.number;
  e.start3 = block.start, e.end3 = block.end;
  e.rational = false;
  e.a = sh.approach ? sh.p3 : sh.p4;
  e.b = sh.approach ? sh.p4 : sh.p3;
  e.start_dir = sh.start_dir, e.end_dir = sh.end_dir;
  if (!sh.circle) {
    e.kind = ContourElement::Kind::kLine;
    e.d = sh.start_dir;  // = b - a = u L, by construction
    e.length = sh.size;  // |d| = L, no root
    e.normal = Vector(-e.d.y(), e.d.x()) / sh.size;
    return e;
  }
  e.kind = ContourElement::Kind::kArc;
  e.centre = sh.centre;
  e.radius = sh.size;
  e.sense = sh.sense;
  return e;
}

ContourElement exact_line(const Block& block, const Point& a, const Point& b) {
  ContourElement e;
  e.kind = ContourElement::Kind::kLine;
  e.line = block.words.line;
  e.number = block.words.number;
  e.start3 = block.start, e.end3 = block.end;
  e.rational = false;
  e.a = a, e.b = b;
  e.d = b - a;
  e.start_dir = e.end_dir = e.d;
  e.length = exact_root(e.d.squared_length());
  e.normal = Vector(-e.d.y(), e.d.x()) / e.length;
  return e;
}

}  // namespace cutcom::ref
