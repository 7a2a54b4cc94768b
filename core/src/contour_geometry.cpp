// NC-CONTOUR-1/2: roundings and chamfers at a corner of two plane elements, on enclosures.
#include "contour_geometry.hpp"

#include <fmt/format.h>

namespace cutcom::contour {

IPoint in_plane(const Point3& p, PlaneAxes ax) {
  return {Interval(coord(p, ax.abscissa)), Interval(coord(p, ax.ordinate))};
}
IPoint operator+(const IPoint& p, const IPoint& q) { return {p.a + q.a, p.o + q.o}; }
IPoint operator-(const IPoint& p, const IPoint& q) { return {p.a - q.a, p.o - q.o}; }
IPoint operator*(const Interval& k, const IPoint& p) { return {k * p.a, k * p.o}; }
Interval dot(const IPoint& p, const IPoint& q) { return p.a * q.a + p.o * q.o; }
Interval cross(const IPoint& p, const IPoint& q) { return p.a * q.o - p.o * q.a; }
IPoint perp(const IPoint& p) { return {-p.o, p.a}; }
Interval norm(const IPoint& p) { return sqrt(dot(p, p)); }
IPoint turned(const IPoint& p, Decimal degrees) {
  Interval c = Interval::cos_deg(degrees), s = Interval::sin_deg(degrees);
  return {c * p.a - s * p.o, s * p.a + c * p.o};
}

IPoint Element::tangent_at_start() const { return arc ? Interval::integer(sense) * perp(start - centre) : end - start; }
IPoint Element::tangent_at_end() const { return arc ? Interval::integer(sense) * perp(end - centre) : end - start; }

Element element_of(const Block& b) {
  PlaneAxes ax = plane_axes(b.state.plane);
  Element e;
  e.start = in_plane(b.start, ax);
  e.end = in_plane(b.end, ax);
  if (!b.is_arc()) return e;
  e.arc = true;
  e.sense = b.state.motion == Motion::kArcCcw ? 1 : -1;
  bool same = coord(b.start, ax.abscissa) == coord(b.end, ax.abscissa) &&
              coord(b.start, ax.ordinate) == coord(b.end, ax.ordinate);
  IPoint d = e.end - e.start;
  IPoint m = Interval::integer(1) / Interval::integer(2) * (e.start + e.end);
  if (b.centre) {
    IPoint c = in_plane(*b.centre, ax);
    if (same) {
      e.full = true;
      e.centre = c;
    } else {  // ARC-CENTRE-1: projected onto the chord's bisector
      IPoint p = perp(d);
      e.centre = m + (dot(c - m, p) / dot(p, p)) * p;
    }
  } else {
    if (!b.words.cr || same) throw ContourError{"a circle given by CR= needs a chord"};
    Interval cr(*b.words.cr);
    Interval q = cr * cr / dot(d, d) - Interval::integer(1) / Interval::integer(4);
    if (q.sign() < 0) {  // ARC-CR-1: up to two grid units beyond 2|CR| is a half circle
      Decimal radius = b.words.cr->sign() < 0 ? -*b.words.cr : *b.words.cr;
      Interval reach = Interval::integer(2) * Interval(radius) + Interval(Decimal::from_units(2));
      if ((dot(d, d) - reach * reach).sign() > 0)
        throw ContourError{"the circle cannot reach its end point with this CR= (alarm 14040)"};
      q = Interval();
    }
    int k = ((e.sense > 0) == (b.words.cr->sign() > 0)) ? 1 : -1;  // ARC-CR-1
    e.centre = m + (Interval::integer(k) * sqrt(q)) * perp(d);
  }
  e.radius = norm(e.start - e.centre);
  return e;
}

Interval sweep(const IPoint& c, const IPoint& from, const IPoint& to, int sense) {
  IPoint u = from - c, v = to - c;
  // The angle from u to v counter-clockwise, in (-π, π], then turned into [0, 2π) for the sense.
  // On the branch cut (u, v parallel) it is exactly 0 or π (NC-GRID-1: an undecided sign is 0).
  Interval y = cross(u, v), x = dot(u, v);
  Interval angle = y.sign() != 0 ? atan2(y, x) : x.sign() > 0 ? Interval() : Interval::pi();
  if (sense < 0) angle = -angle;
  Interval two_pi = Interval::integer(2) * Interval::pi();
  if (angle.sign() < 0) angle = angle + two_pi;
  return angle;
}

namespace {

// The point of `e`'s circle or line at distance `d` from the corner point `p` (the end of e when
// `before`, else its start), on the element's side of the corner.
IPoint at_distance(const Element& e, const IPoint& p, const Interval& d, bool before) {
  IPoint t = before ? e.tangent_at_end() : e.tangent_at_start();
  Interval dir = Interval::integer(before ? -1 : 1);
  if (!e.arc) return p + (dir * d / norm(t)) * t;
  // Circle about c through p meets the circle of radius d about p in two points symmetric to cp.
  IPoint cp = p - e.centre;
  Interval rr = dot(cp, cp);
  // Along cp from p: x = -d²/(2ρ); across: y = ±sqrt(d² - x²).
  Interval rho = sqrt(rr);
  Interval x = -(d * d) / (Interval::integer(2) * rho);
  Interval y2 = d * d - x * x;
  if (y2.sign() < 0) throw ContourError{"does not fit on the circle"};
  IPoint u = (Interval::integer(1) / rho) * cp;  // unit, centre -> p
  IPoint n = perp(u);
  Interval y = sqrt(y2);
  IPoint q1 = p + x * u + y * n, q2 = p + x * u - y * n;
  return dot(q1 - p, t).sign() * (before ? -1 : 1) > 0 ? q1 : q2;
}

// Is `x` (on the element's carrier) within the element, between its start and end?
bool within(const Element& e, const IPoint& x) {
  if (!e.arc) {
    IPoint t = e.end - e.start;
    Interval lambda = dot(x - e.start, t) / dot(t, t);
    return lambda.sign() >= 0 && (Interval::integer(1) - lambda).sign() >= 0;
  }
  if (e.full) return true;
  Interval whole = sweep(e.centre, e.start, e.end, e.sense);
  Interval part = sweep(e.centre, e.start, x, e.sense);
  return (whole - part).sign() >= 0;
}

// Offset carrier of an element towards side s (+1 left) at distance r: a line (point, direction)
// or a circle (centre, radius).
struct Carrier {
  bool circle = false;
  IPoint point, direction;
  Interval radius;
};
Carrier offset(const Element& e, int s, const Interval& r) {
  Carrier c;
  if (!e.arc) {
    IPoint t = e.end - e.start;
    c.point = e.start + (Interval::integer(s) * r / norm(t)) * perp(t);
    c.direction = t;
    return c;
  }
  c.circle = true;
  c.point = e.centre;
  c.radius = e.radius - Interval::integer(s * e.sense) * r;  // TRC-ARC-EQ-1's rule
  if (c.radius.sign() <= 0) throw ContourError{"the rounding is larger than the circle"};
  return c;
}

// Intersections of two carriers (0, 1 or 2 points).
int intersect(const Carrier& c1, const Carrier& c2, IPoint out[2]) {
  if (!c1.circle && !c2.circle) {
    Interval den = cross(c1.direction, c2.direction);
    if (den.sign() == 0) return 0;
    Interval u = cross(c2.point - c1.point, c2.direction) / den;
    out[0] = c1.point + u * c1.direction;
    return 1;
  }
  if (!c1.circle || !c2.circle) {
    const Carrier& l = c1.circle ? c2 : c1;
    const Carrier& c = c1.circle ? c1 : c2;
    // |q + u t - c|² = R²: a u² + 2 b u + k = 0
    IPoint w = l.point - c.point;
    Interval a = dot(l.direction, l.direction), b = dot(w, l.direction), k = dot(w, w) - c.radius * c.radius;
    Interval disc = b * b - a * k;
    if (disc.sign() < 0) return 0;
    Interval root = sqrt(disc);
    out[0] = l.point + ((-b - root) / a) * l.direction;
    out[1] = l.point + ((-b + root) / a) * l.direction;
    return 2;
  }
  IPoint d = c2.point - c1.point;
  Interval dd = dot(d, d);
  if (dd.sign() == 0) return 0;
  // Along d: x = (dd + R1² - R2²) / (2|d|) from c1; across: ±sqrt(R1² - x²).
  Interval x_over = (dd + c1.radius * c1.radius - c2.radius * c2.radius) / (Interval::integer(2) * dd);
  Interval h2 = c1.radius * c1.radius / dd - x_over * x_over;
  if (h2.sign() < 0) return 0;
  Interval h = sqrt(h2);
  IPoint base = c1.point + x_over * d;
  out[0] = base + h * perp(d);
  out[1] = base - h * perp(d);
  return 2;
}

}  // namespace

namespace {

// The rounding of radius r at the corner (p the corner point, s its turn), without the fit check.
CornerCut rounding_at(const Element& e1, const Element& e2, int s, const IPoint& p, const Interval& r) {
  Carrier c1 = offset(e1, s, r), c2 = offset(e2, s, r);
  IPoint cand[2];
  int n = intersect(c1, c2, cand);
  if (n == 0) throw ContourError{"no circle of this radius touches both elements"};
  IPoint f = cand[0];
  if (n == 2 && (dot(cand[1] - p, cand[1] - p) - dot(cand[0] - p, cand[0] - p)).sign() < 0) f = cand[1];
  auto foot = [&](const Element& e) {
    if (!e.arc) {
      IPoint t = e.end - e.start;
      return e.start + (dot(f - e.start, t) / dot(t, t)) * t;
    }
    IPoint cf = f - e.centre;
    return e.centre + (e.radius / norm(cf)) * cf;
  };
  CornerCut cut;
  cut.t1 = foot(e1), cut.t2 = foot(e2);
  cut.arc = true, cut.centre = f, cut.sense = s;
  cut.value = r;
  return cut;
}

// The unit normal of `e` at its point `x`, towards side s (+1 left of the direction of travel).
IPoint normal_at(const Element& e, const IPoint& x, int s) {
  if (!e.arc) {
    IPoint t = e.end - e.start;
    return (Interval::integer(s) / norm(t)) * perp(t);
  }
  return (Interval::integer(-s * e.sense) / e.radius) * (x - e.centre);
}

// The radius of the rounding that touches `pinned` exactly at its point x and touches `other`:
// the centre x + r·n lies on other's carrier offset by r (linear in r). nullopt: no such radius.
std::optional<Interval> radius_touching_at(const Element& pinned, const IPoint& x, const Element& other, int s) {
  IPoint n = normal_at(pinned, x, s);
  Interval num, den;
  if (!other.arc) {  // signed distance of the centre from the line equals s·r
    IPoint d = other.end - other.start;
    num = -cross(x - other.start, d);
    den = cross(n, d) + Interval::integer(s) * norm(d);
  } else {  // |x + r n - C| = R - s·sense·r
    IPoint w = x - other.centre;
    num = other.radius * other.radius - dot(w, w);
    den = Interval::integer(2) * (dot(n, w) + Interval::integer(s * other.sense) * other.radius);
  }
  if (den.sign() == 0) return std::nullopt;
  Interval r = num / den;
  if (r.sign() <= 0) return std::nullopt;
  return r;
}

// The longest chamfer leg that `e` offers from its corner end to its far end (`far`): a line's
// length, a circle's chord to its far end, or its diameter where the circle turns beyond π.
Interval longest_leg(const Element& e, const IPoint& corner, const IPoint& far) {
  if (!e.arc) return norm(far - corner);
  if (!e.full && (sweep(e.centre, e.start, e.end, e.sense) - Interval::pi()).sign() <= 0) return norm(far - corner);
  return Interval::integer(2) * e.radius;
}

bool fits(const Element& e1, const Element& e2, const CornerCut& cut) {
  return within(e1, cut.t1) && within(e2, cut.t2);
}

}  // namespace

std::optional<CornerCut> cut_corner(const Element& e1, const Element& e2, CornerKind kind, const Interval& value) {
  IPoint p = e1.end;
  IPoint t1 = e1.tangent_at_end(), t2 = e2.tangent_at_start();
  int s = cross(t1, t2).sign();
  if (s == 0) {
    if (dot(t1, t2).sign() > 0) return std::nullopt;  // tangent: no corner
    throw ContourError{"the contour reverses at the corner"};
  }
  if (kind == CornerKind::kRounding) {
    try {
      CornerCut cut = rounding_at(e1, e2, s, p, value);
      if (fits(e1, e2, cut)) return cut;
    } catch (const ContourError&) {  // too large for a circle of the corner: reduced below
    }
    // NC-CONTOUR-1: the control reduces a rounding that does not fit; cutcom takes the largest
    // that fits, touching the shorter element at its far end.
    std::optional<Interval> best;
    for (auto r : {radius_touching_at(e1, e1.start, e2, s), radius_touching_at(e2, e2.end, e1, s)})
      if (r && (*r - value).sign() < 0 && (!best || (*r - *best).sign() < 0)) best = r;
    if (!best) throw ContourError{"does not fit on the elements of the corner"};
    CornerCut cut = rounding_at(e1, e2, s, p, *best);
    if (!fits(e1, e2, cut)) throw ContourError{"does not fit on the elements of the corner"};
    cut.reduced = true;
    return cut;
  }
  // CHF: the chamfer's own length c; its legs d = c / (2 cos(θ/2)).
  Interval cos_half;
  Interval d = value;
  if (kind == CornerKind::kChamferLength) {
    Interval cos_t = dot(t1, t2) / (norm(t1) * norm(t2));
    cos_half = sqrt((Interval::integer(1) + cos_t) / Interval::integer(2));
    d = value / (Interval::integer(2) * cos_half);
  }
  // NC-CONTOUR-1: legs longer than an element are reduced to the longest that fits.
  Interval longest = longest_leg(e1, p, e1.start), other = longest_leg(e2, p, e2.end);
  if ((other - longest).sign() < 0) longest = other;
  CornerCut cut;
  if ((d - longest).sign() > 0) d = longest, cut.reduced = true;
  cut.t1 = at_distance(e1, p, d, true);
  cut.t2 = at_distance(e2, p, d, false);
  cut.value = kind == CornerKind::kChamferLength ? Interval::integer(2) * d * cos_half : d;
  if (!fits(e1, e2, cut)) throw ContourError{"does not fit on the elements of the corner"};
  return cut;
}

}  // namespace cutcom::contour
