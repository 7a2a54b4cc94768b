#include "contour_element.hpp"

namespace cutcom::ref {

ContourLine ContourLine::of(const Block& block, PlaneAxes axes) {
  ContourLine l;
  l.line = block.words.line;
  l.number = block.words.number;
  l.start3 = block.start;
  l.end3 = block.end;
  l.dx = units_of(coord(block.end, axes.abscissa)) - units_of(coord(block.start, axes.abscissa));
  l.dy = units_of(coord(block.end, axes.ordinate)) - units_of(coord(block.start, axes.ordinate));
  l.a = plane_point(block.start, axes);
  l.b = plane_point(block.end, axes);
  l.d = l.b - l.a;
  mpz_class sq = l.dx * l.dx + l.dy * l.dy;
  l.length = CGAL::sqrt(FT(CORE::BigInt(sq.get_mpz_t())));
  l.normal = Vector(-l.d.y() / l.length, l.d.x() / l.length);
  return l;
}

CornerClass classify_corner(const ContourLine& first, const ContourLine& second, int side) {
  CornerClass c;
  c.cross = first.dx * second.dy - first.dy * second.dx;
  c.dot = first.dx * second.dx + first.dy * second.dy;
  c.squared_lengths_product =
      (first.dx * first.dx + first.dy * first.dy) * (second.dx * second.dx + second.dy * second.dy);
  int turn = sgn(c.cross) * side;  // > 0: the tool is on the inside of the turn
  if (sgn(c.cross) == 0)
    c.kind = sgn(c.dot) > 0 ? CornerKind::kTangent : CornerKind::kReversal;
  else
    c.kind = turn > 0 ? CornerKind::kInner : CornerKind::kOuter;
  return c;
}

}  // namespace cutcom::ref
