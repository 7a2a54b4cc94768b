#include "contour_element.hpp"

namespace cutcom::ref {

FT to_ft(const mpq_class& q) {
  if (q.get_den() == 1) return FT(CORE::BigInt(q.get_num().get_mpz_t()));
  return FT(CORE::BigRat(q.get_mpq_t()));
}

// The square root of a rational q >= 0: the rational itself when numerator and denominator are
// squares (a radius I4.969, an axis-parallel line), else CORE's root. The value is the same; a
// rational keeps the expressions built on it shallow, so that CORE proves their zeros cheaply.
FT rational_root(const mpq_class& q) {
  if (sgn(q) == 0) return FT(0);
  if (mpz_perfect_square_p(q.get_num_mpz_t()) != 0 && mpz_perfect_square_p(q.get_den_mpz_t()) != 0) {
    mpz_class n, d;
    mpz_sqrt(n.get_mpz_t(), q.get_num_mpz_t());
    mpz_sqrt(d.get_mpz_t(), q.get_den_mpz_t());
    return to_ft(mpq_class(n, d));
  }
  return CGAL::sqrt(to_ft(q));
}

namespace {
mpq_class units_q(const Decimal& d) { return mpq_class(to_mpz(d)); }

// sigma * perp(p - c) = sigma * (-(p_b - c_b), p_a - c_a): the direction of travel at p.
RationalVector arc_tangent(const mpq_class& pa, const mpq_class& pb, const mpq_class& ca, const mpq_class& cb,
                           int sense) {
  return {-sense * (pb - cb), sense * (pa - ca)};
}
}  // namespace

ContourElement ContourElement::of_line(const Block& block, PlaneAxes axes) {
  ContourElement e;
  e.kind = Kind::kLine;
  e.line = block.words.line;
  e.number = block.words.number;
  e.start3 = block.start;
  e.end3 = block.end;
  mpz_class dx = to_mpz(coord(block.end, axes.abscissa)) - to_mpz(coord(block.start, axes.abscissa));
  mpz_class dy = to_mpz(coord(block.end, axes.ordinate)) - to_mpz(coord(block.start, axes.ordinate));
  e.start_tangent = e.end_tangent = {mpq_class(dx), mpq_class(dy)};
  e.start_dir = e.end_dir = Vector(to_ft(dx), to_ft(dy));
  e.a = plane_point(block.start, axes);
  e.b = plane_point(block.end, axes);
  e.d = e.b - e.a;
  mpz_class sq = dx * dx + dy * dy;
  e.length = rational_root(mpq_class(sq));
  e.normal = Vector(-e.d.y() / e.length, e.d.x() / e.length);
  return e;
}

namespace {
// What both kinds of circle take from their block.
ContourElement arc_of(const Block& block) {
  ContourElement e;
  e.kind = ContourElement::Kind::kArc;
  e.line = block.words.line;
  e.number = block.words.number;
  e.start3 = block.start;
  e.end3 = block.end;
  e.sense = block.state.motion == Motion::kArcCcw ? 1 : -1;
  return e;
}

// ARC-CR-1: the centre of a CR= circle, on the side of the chord that makes it the short arc for
// CR > 0 and the long one for CR < 0: m + k perp(d) sqrt(CR^2/|d|^2 - 1/4), k = +1 for G3 with
// CR > 0 or G2 with CR < 0.
ContourElement of_cr_arc(const Block& block, PlaneAxes axes) {
  ContourElement e = arc_of(block);
  e.rational = false;
  mpq_class sa = units_q(coord(block.start, axes.abscissa)), sb = units_q(coord(block.start, axes.ordinate));
  mpq_class ea = units_q(coord(block.end, axes.abscissa)), eb = units_q(coord(block.end, axes.ordinate));
  mpq_class cr = units_q(*block.words.cr);
  mpq_class da = ea - sa, db = eb - sb;
  mpq_class q = cr * cr / (da * da + db * db) - mpq_class(1, 4);
  int k = (e.sense > 0) == (sgn(cr) > 0) ? 1 : -1;
  FT h = sgn(q) <= 0 ? FT(0) : rational_root(q);  // (q < 0: a rounding beyond a half circle)
  e.a = plane_point(block.start, axes);
  e.b = plane_point(block.end, axes);
  e.centre = Point(to_ft((sa + ea) / 2) + FT(k) * (-to_ft(db)) * h, to_ft((sb + eb) / 2) + FT(k) * to_ft(da) * h);
  e.radius_squared = cr * cr;
  e.radius = to_ft(abs(cr));
  if (sgn(q) < 0) {  // a chord a rounding longer than 2|CR| (ARC-CR-1): a half circle about its midpoint
    e.radius_squared = (da * da + db * db) / 4;
    e.radius = rational_root(e.radius_squared);
  }
  Vector rs = e.a - e.centre, re = e.b - e.centre;
  e.start_dir = Vector(-rs.y(), rs.x()) * FT(e.sense);
  e.end_dir = Vector(-re.y(), re.x()) * FT(e.sense);
  return e;
}
}  // namespace

ContourElement ContourElement::of_arc(const Block& block, PlaneAxes axes) {
  if (!block.centre) return of_cr_arc(block, axes);
  ContourElement e = arc_of(block);
  mpq_class sa = units_q(coord(block.start, axes.abscissa)), sb = units_q(coord(block.start, axes.ordinate));
  mpq_class ea = units_q(coord(block.end, axes.abscissa)), eb = units_q(coord(block.end, axes.ordinate));
  mpq_class ca = units_q(coord(*block.centre, axes.abscissa)), cb = units_q(coord(*block.centre, axes.ordinate));
  e.full_circle = sa == ea && sb == eb;
  if (!e.full_circle) {
    // ARC-CENTRE-1: the programmed centre projected onto the perpendicular bisector of the chord,
    // so that start and end lie exactly on one circle: c' = m + ((c - m) . p / |p|^2) p,
    // p = perp(e - s), m the midpoint. Rational.
    mpq_class ma = (sa + ea) / 2, mb = (sb + eb) / 2;
    mpq_class pa = -(eb - sb), pb = ea - sa;
    mpq_class k = ((ca - ma) * pa + (cb - mb) * pb) / (pa * pa + pb * pb);
    ca = ma + k * pa;
    cb = mb + k * pb;
  }
  e.cx = ca, e.cy = cb;
  e.radius_squared = (sa - ca) * (sa - ca) + (sb - cb) * (sb - cb);
  e.centre = Point(to_ft(ca), to_ft(cb));
  e.radius = rational_root(e.radius_squared);
  e.start_tangent = arc_tangent(sa, sb, ca, cb, e.sense);
  e.end_tangent = arc_tangent(ea, eb, ca, cb, e.sense);
  e.start_dir = Vector(to_ft(e.start_tangent.a), to_ft(e.start_tangent.b));
  e.end_dir = Vector(to_ft(e.end_tangent.a), to_ft(e.end_tangent.b));
  e.a = plane_point(block.start, axes);
  e.b = plane_point(block.end, axes);
  return e;
}

Vector ContourElement::start_normal() const {
  if (kind == Kind::kLine) return normal;
  // Left of the direction of travel: towards the centre for ccw, away from it for cw.
  return (centre - a) * FT(sense) / radius;
}

Vector ContourElement::end_normal() const {
  if (kind == Kind::kLine) return normal;
  return (centre - b) * FT(sense) / radius;
}

CornerKind classify_corner(const Vector& t1, const Vector& t2, int side) {
  CGAL::Sign cross = CGAL::sign(t1.x() * t2.y() - t1.y() * t2.x());
  if (cross == CGAL::ZERO) return CGAL::sign(t1 * t2) == CGAL::POSITIVE ? CornerKind::kTangent : CornerKind::kReversal;
  return static_cast<int>(cross) * side > 0 ? CornerKind::kInner : CornerKind::kOuter;
}

CornerClass classify_corner(const RationalVector& t1, const RationalVector& t2, int side) {
  CornerClass c;
  c.cross = t1.a * t2.b - t1.b * t2.a;
  c.dot = t1.a * t2.a + t1.b * t2.b;
  // Positive scalings to integers keep every angle.
  mpz_class k1 = lcm(t1.a.get_den(), t1.b.get_den()), k2 = lcm(t2.a.get_den(), t2.b.get_den());
  c.a1 = mpz_class(t1.a * k1), c.b1 = mpz_class(t1.b * k1);
  c.a2 = mpz_class(t2.a * k2), c.b2 = mpz_class(t2.b * k2);
  int turn = sgn(c.cross) * side;  // > 0: the tool is on the inside of the turn
  if (sgn(c.cross) == 0)
    c.kind = sgn(c.dot) > 0 ? CornerKind::kTangent : CornerKind::kReversal;
  else
    c.kind = turn > 0 ? CornerKind::kInner : CornerKind::kOuter;
  return c;
}

}  // namespace cutcom::ref
