#include "plane_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cutcom::fast {

namespace {
double sweep_of(const Element& e) {
  if (e.full) return 2 * std::numbers::pi;
  double a = signed_rotation(e.start - e.centre, e.end - e.centre, e.sense);
  return a > 0 ? a : a + 2 * std::numbers::pi;
}
}  // namespace

Element Element::line(Vec2 s, Vec2 e) {
  Element l;
  l.start = s, l.end = e;
  Vec2 d = e - s;
  l.length = norm(d);
  l.unit = (1.0 / l.length) * d;
  return l;
}

Element Element::line_along(Vec2 s, Vec2 e, Vec2 unit) {
  Element l;
  l.start = s, l.end = e;
  l.length = norm(e - s);
  l.unit = unit;
  return l;
}

Element Element::circle(Vec2 s, Vec2 e, Vec2 c, int sense) {
  Element a;
  a.arc = true;
  a.start = s, a.end = e, a.sense = sense;
  a.full = s.a == e.a && s.b == e.b;
  if (!a.full) {
    // ARC-CENTRE-1: project the programmed centre onto the chord's perpendicular bisector.
    Vec2 m = 0.5 * (s + e);
    Vec2 p = left_normal(e - s);
    c = m + (dot(c - m, p) / dot(p, p)) * p;
  }
  a.centre = c;
  a.radius = norm(s - c);
  a.turn = sweep_of(a);
  return a;
}

Element Element::circle_by_radius(Vec2 s, Vec2 e, double cr, int sense, double q, Vec2 chord) {
  Element a;
  a.arc = true;
  a.start = s, a.end = e, a.sense = sense;
  Vec2 d = std::isnan(chord.a) ? e - s : chord;
  if (std::isnan(q)) q = cr * cr / dot(d, d) - 0.25;
  double h = q > 0 ? std::sqrt(q) : 0;
  int k = (sense > 0) == (cr > 0) ? 1 : -1;  // short arc for CR > 0, long for CR < 0
  a.centre = 0.5 * (s + e) + (k * h) * left_normal(d);
  // ARC-CR-1: a chord a rounding longer than 2|CR| is a half circle about its midpoint.
  a.radius = q >= 0 ? std::fabs(cr) : 0.5 * norm(d);
  a.turn = sweep_of(a);
  return a;
}

Corner classify_corner(Vec2 t1, Vec2 t2, int side) {
  Corner c;
  double sn = cross(t1, t2);
  double cs = dot(t1, t2);
  c.sine = side * sn;
  c.cosine = cs;
  if (sn == 0)
    c.kind = cs > 0 ? Corner::Kind::kTangent : Corner::Kind::kReversal;
  else
    c.kind = c.sine > 0 ? Corner::Kind::kInner : Corner::Kind::kOuter;
  return c;
}

double corner_trim(const Corner& c, int side, double radius) {
  if (radius == 0) return 0;  // the corner itself (a reversal's tan of half the turn is infinite)
  // tan(phi/2) = sin/(1+cos) = (1-cos)/sin: the form without cancellation, chosen by cos's sign.
  double sn = side * c.sine;
  double tan_half = c.cosine >= 0 ? sn / (1 + c.cosine) : (1 - c.cosine) / sn;
  return side * radius * tan_half;
}

namespace {
// Two circles' common points lie on the line of centres at `along` times d from the smaller
// circle's centre, across it by sqrt(across2) times |d|. From the larger one, across2 = R^2 / d^2
// - along^2 cancels to about (rho / d)^2 and keeps only rho / d of its digits (seed 20261294,
// case 97596: a circle of 0.007 mm on one of 48 mm, 1.1e-10 mm off). carrier_intersections and
// carrier_gap decide on the same across2 (PROP-BOUNDARY-1).
struct CentreLine {
  const Carrier* from;  // the smaller circle (u of equal ones)
  Vec2 d;               // to the other centre
  double dd = 0, along = 0, across2 = 0;
};
CentreLine centre_line(const Carrier& u, const Carrier& v) {
  const bool from_v = v.radius < u.radius;
  const Carrier& a = from_v ? v : u;
  const Carrier& b = from_v ? u : v;
  CentreLine l{&a, b.point - a.point};
  l.dd = dot(l.d, l.d);
  if (l.dd == 0) return l;
  l.along = (a.radius * a.radius - b.radius * b.radius + l.dd) / (2 * l.dd);
  l.across2 = a.radius * a.radius / l.dd - l.along * l.along;
  return l;
}
}  // namespace

int carrier_intersections(const Carrier& u, const Carrier& v, Vec2 out[2]) {
  if (!u.circle && !v.circle) {
    double den = cross(u.direction, v.direction);
    if (den == 0) return 0;
    double t = cross(v.point - u.point, v.direction) / den;
    out[0] = u.point + t * u.direction;
    return 1;
  }
  if (u.circle != v.circle) {
    const Carrier& l = u.circle ? v : u;
    const Carrier& c = u.circle ? u : v;
    // Foot of the perpendicular from the centre, then half the chord along the line.
    Vec2 d = (1.0 / norm(l.direction)) * l.direction;
    Vec2 foot = l.point + dot(c.point - l.point, d) * d;
    double dist2 = dot(foot - c.point, foot - c.point);
    double half2 = c.radius * c.radius - dist2;
    if (half2 < 0) return 0;
    double h = std::sqrt(half2);
    out[0] = foot - h * d, out[1] = foot + h * d;
    return h > 0 ? 2 : 1;
  }
  CentreLine l = centre_line(u, v);
  if (l.dd == 0 || l.across2 < 0) return 0;
  Vec2 m = l.from->point + l.along * l.d;
  double h = std::sqrt(l.across2);
  // In ref's order: first the point to the left of the direction from u's centre to v's.
  Vec2 left = l.from == &u ? left_normal(l.d) : -1.0 * left_normal(l.d);
  out[0] = m + h * left, out[1] = m - h * left;
  return h > 0 ? 2 : 1;
}

// Of two intersections the nearer; of two equally near the one further along `ahead`.
bool nearest_intersection(const Carrier& u, const Carrier& v, Vec2 near, Vec2 ahead, Vec2& out, NearerChoice* choice) {
  Vec2 xs[2];
  int n = carrier_intersections(u, v, xs);
  if (n == 0) return false;
  NearerChoice c = n == 2 ? nearer_choice(u, v, xs, near, ahead) : NearerChoice{};
  out = xs[c.second ? 1 : 0];
  if (choice) *choice = c;
  return true;
}

// Which is nearer from the carriers, as ref decides it (second_farther), not from the points' own
// distances, which differ by a rounding where the carriers nearly touch (seed 20261276, case
// 342258: 1.3e-13 mm). `near` exactly on the axis (aligned centres, common in programs and in
// SAR's circles by construction) is an exact tie, which fast takes as one within its error: that
// of the carriers' data (SAR's circles are computed), which moves the points along the chord by
// up to intersection_error and the axis with them.
NearerChoice nearer_choice(const Carrier& u, const Carrier& v, const Vec2 xs[2], Vec2 near, Vec2 ahead) {
  // `across` points from the first of carrier_intersections' points to the second (ref's order).
  Vec2 on_axis, across;
  if (u.circle != v.circle) {
    const Carrier& l = u.circle ? v : u;
    on_axis = (u.circle ? u : v).point, across = l.direction;
  } else {
    on_axis = u.point, across = -1.0 * left_normal(v.point - u.point);
  }
  NearerChoice c;
  c.first_nearer = dot(on_axis - near, across) / norm(across);
  double band = 2 * intersection_error(u, v, xs[0]) +
                64 * std::numeric_limits<double>::epsilon() *
                    (std::fabs(near.a) + std::fabs(near.b) + std::fabs(on_axis.a) + std::fabs(on_axis.b));
  if (std::fabs(c.first_nearer) <= band) c.first_nearer = 0;  // equally near within fast's error
  // A tie takes the one further along `ahead` (across it exactly: the first, as ref).
  c.second = c.first_nearer == 0 ? dot(across, ahead) > 0 : c.first_nearer < 0;
  return c;
}

namespace {
// Carriers at a corner that miss by less than the rounding of their own data: for the exact data
// they may as well cross. An inserted rounding (NC-CONTOUR-1) is tangent to its neighbours to
// within its grid point, so with the tool outside it the offsets cross by 1e-21 mm, which double
// shows as a miss of 1e-15 mm: an alarm 10751 where ref finds the intersection.
bool misses_within_rounding(const Carrier& u, const Carrier& v, double gap) {
  if (!(gap > 0)) return false;
  if (u.circle && v.circle && u.point.a == v.point.a && u.point.b == v.point.b) return false;  // concentric
  double size = 0;
  for (const Carrier* c : {&u, &v})
    size = std::max(size, std::fabs(c->point.a) + std::fabs(c->point.b) + (c->circle ? c->radius : 0));
  return gap <= 64 * std::numeric_limits<double>::epsilon() * size;
}

// Where two carriers that miss within rounding touch: the line's point nearest the centre, or the
// point of the first circle on the line of centres facing the second.
Vec2 touching_point(const Carrier& u, const Carrier& v) {
  if (u.circle != v.circle) {
    const Carrier& l = u.circle ? v : u;
    const Carrier& c = u.circle ? u : v;
    Vec2 d = (1.0 / norm(l.direction)) * l.direction;
    return l.point + dot(c.point - l.point, d) * d;
  }
  Vec2 d = v.point - u.point;
  double k = u.radius / norm(d);
  bool inside = v.radius > u.radius && norm(d) < v.radius;  // u inside v: it touches away from v's centre
  return u.point + (inside ? -k : k) * d;
}
}  // namespace

// TRC-ARC-CORNER-1 with tool radius 0: the carriers are the programmed elements, which both pass
// through the corner, the nearest intersection there is (at distance 0). From the carriers it
// would land up to sqrt(u) times their size away where they nearly touch (campaign 20261129,
// case 223714: a full circle after it became a sliver). Carriers that miss within rounding touch.
bool corner_intersection(const Carrier& u, const Carrier& v, Vec2 corner, Vec2 ahead, double r, Vec2& out) {
  if (r == 0) return out = corner, true;
  if (nearest_intersection(u, v, corner, ahead, out)) return true;
  if (!(u.circle || v.circle) || !misses_within_rounding(u, v, carrier_gap(u, v))) return false;
  out = touching_point(u, v);
  return true;
}

bool touching_within_rounding(const Carrier& u, const Carrier& v, Vec2& out) {
  if (!(u.circle || v.circle)) return false;
  double gap = carrier_gap(u, v);
  if (!misses_within_rounding(u, v, gap == 0 ? std::numeric_limits<double>::denorm_min() : std::fabs(gap)))
    return false;
  out = touching_point(u, v);
  return true;
}

double corner_gap(const Carrier& u, const Carrier& v, double r) {
  double gap = carrier_gap(u, v);
  // With radius 0 they meet at the corner; within rounding of touching they touch.
  return r == 0 || misses_within_rounding(u, v, gap) ? std::min(gap, 0.0) : gap;
}

double intersection_error(const Carrier& u, const Carrier& v, Vec2 x) {
  auto unit_tangent = [&](const Carrier& c) {
    Vec2 t = c.circle ? left_normal(x - c.point) : c.direction;
    return (1.0 / norm(t)) * t;
  };
  double size = std::fabs(x.a) + std::fabs(x.b);
  for (const Carrier* c : {&u, &v}) size += std::fabs(c->point.a) + std::fabs(c->point.b) + (c->circle ? c->radius : 0);
  double crossing = std::fabs(cross(unit_tangent(u), unit_tangent(v)));
  double error = 64 * std::numeric_limits<double>::epsilon() * size;
  return crossing > 0 ? error / crossing : std::numeric_limits<double>::infinity();
}

bool on_one_line(const Carrier& u, const Carrier& v) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  Vec2 du = (1.0 / norm(u.direction)) * u.direction, dv = (1.0 / norm(v.direction)) * v.direction;
  double size = std::fabs(u.point.a) + std::fabs(u.point.b) + std::fabs(v.point.a) + std::fabs(v.point.b);
  return std::fabs(cross(du, dv)) <= 16 * eps && std::fabs(cross(du, v.point - u.point)) <= 64 * eps * size;
}

bool on_one_circle(const Carrier& u, const Carrier& v) {
  if (!u.circle || !v.circle) return false;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double size =
      std::fabs(u.point.a) + std::fabs(u.point.b) + std::fabs(v.point.a) + std::fabs(v.point.b) + u.radius + v.radius;
  return norm(v.point - u.point) <= 64 * eps * size && std::fabs(u.radius - v.radius) <= 64 * eps * size;
}

// The sign is that of the quantity carrier_intersections decides on (PROP-BOUNDARY-1: the
// branch "meet" or "miss" must agree with the margin traced), the size the distance in mm.
double carrier_gap(const Carrier& u, const Carrier& v) {
  // A margin that rounds to 0 (or underflows) keeps the sign of the decision: carriers that miss
  // by less than the doubles can show have a positive gap, the smallest there is.
  auto missing = [](double g) { return g > 0 ? g : std::numeric_limits<double>::denorm_min(); };
  if (u.circle != v.circle) {
    const Carrier& l = u.circle ? v : u;
    const Carrier& c = u.circle ? u : v;
    Vec2 d = (1.0 / norm(l.direction)) * l.direction;
    Vec2 foot = l.point + dot(c.point - l.point, d) * d;
    double dist2 = dot(foot - c.point, foot - c.point);
    double half2 = c.radius * c.radius - dist2;
    double g = -half2 / (c.radius + std::sqrt(dist2));  // = distance of the centre - radius
    return half2 < 0 ? missing(g) : std::min(g, 0.0);
  }
  CentreLine l = centre_line(u, v);
  if (l.dd == 0) return missing(std::fabs(u.radius - v.radius));  // concentric: never meet (or the same circle)
  double dist = std::sqrt(l.dd);
  double gap = std::max(dist - (u.radius + v.radius), std::fabs(u.radius - v.radius) - dist);
  // Within rounding of touching the two formulas may disagree: the deciding one's sign, its size.
  if ((l.across2 < 0) != (gap > 0)) gap = -l.across2 * l.dd / (l.from->radius + std::fabs(l.along) * dist);
  return l.across2 < 0 ? missing(gap) : std::min(gap, 0.0);
}

double signed_rotation(Vec2 from, Vec2 to, int sense) { return sense * std::atan2(cross(from, to), dot(from, to)); }

}  // namespace cutcom::fast
