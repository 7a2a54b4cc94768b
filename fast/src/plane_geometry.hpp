// fast's double-precision plane geometry: vectors in (abscissa, ordinate) of the active plane,
// contour elements (straight or circular), corners and intersections of equidistants.
#pragma once

#include <cmath>
#include <limits>

namespace cutcom::fast {

struct Vec2 {
  double a = 0, b = 0;
};
inline Vec2 operator+(Vec2 p, Vec2 q) { return {p.a + q.a, p.b + q.b}; }
inline Vec2 operator-(Vec2 p, Vec2 q) { return {p.a - q.a, p.b - q.b}; }
inline Vec2 operator*(double k, Vec2 p) { return {k * p.a, k * p.b}; }
inline double dot(Vec2 p, Vec2 q) { return p.a * q.a + p.b * q.b; }
inline double cross(Vec2 p, Vec2 q) { return p.a * q.b - p.b * q.a; }
inline Vec2 left_normal(Vec2 unit) { return {-unit.b, unit.a}; }
// sqrt of the sum of squares, not hypot: within an ulp of it, and hypot took a tenth of a CDON run.
// No overflow below 1e150 mm; sqrt(a * a) is |a| exactly, so lengths along an axis stay exact.
inline double norm(Vec2 p) { return std::sqrt(p.a * p.a + p.b * p.b); }

// A compensated block in plane coordinates: a straight line or a circle (I/J/K).
// The points first, each a multiple of 16 bytes from the start: an element is copied 16 bytes at a
// time, and a point read back soon after from a copy must lie within one of its stores to be
// forwarded (a point at 8 bytes past a boundary waited in a fifth of entry_corner's samples).
struct Element {
  Vec2 start, end;
  Vec2 unit;          // lines: direction of travel
  Vec2 centre;        // arcs: centre on the chord's bisector (ARC-CENTRE-1)
  double length = 0;  // lines: > 0
  double radius = 0;  // arcs
  double turn = 0;    // arcs: the sweep in (0, 2 pi], computed once with the element (an atan2)
  int sense = 1;      // arcs: +1 ccw (G3), -1 cw (G2)
  bool arc = false;
  bool full = false;  // arcs: start = end

  static Element line(Vec2 s, Vec2 e);
  // A line whose direction is known better than its points' difference (a SAR line: its tangent).
  static Element line_along(Vec2 s, Vec2 e, Vec2 unit);
  static Element circle(Vec2 s, Vec2 e, Vec2 programmed_centre, int sense);
  // ARC-CR-1; `q` = CR^2 / chord^2 - 1/4 and `chord` = e - s where the caller has them from exact
  // values (NaN: from the doubles).
  static Element circle_by_radius(Vec2 s, Vec2 e, double cr, int sense,
                                  double q = std::numeric_limits<double>::quiet_NaN(),
                                  Vec2 chord = {std::numeric_limits<double>::quiet_NaN(), 0});

  Vec2 start_tangent() const { return arc ? tangent_at(start) : unit; }  // unit vectors
  Vec2 end_tangent() const { return arc ? tangent_at(end) : unit; }
  Vec2 tangent_at(Vec2 p) const { return (sense / radius) * left_normal(p - centre); }
  // TRC-EQ-1: the equidistant's point for programmed point p with unit tangent t.
  static Vec2 offset(Vec2 p, Vec2 unit_tangent, double side_radius) {
    return p + side_radius * left_normal(unit_tangent);
  }
  // TRC-ARC-EQ-1: radius of a circle's equidistant.
  double equidistant_radius(double side_radius) const { return radius - side_radius * sense; }
};

// The corner between two elements, seen from side s.
struct Corner {
  enum class Kind { kTangent, kInner, kOuter, kReversal } kind;
  double sine;    // s * sin(deflection): > 0 inner, < 0 outer (the TRC-CORNER-1 margin)
  double cosine;  // cos(deflection)
};
Corner classify_corner(Vec2 end_tangent, Vec2 start_tangent, int side);

// Signed shortening s r tan(phi/2) of two straight equidistants at their intersection.
double corner_trim(const Corner& c, int side, double radius);

// An equidistant extended to its carrier, and the carriers' intersection nearest to a point (of
// two equally near, the one further along `ahead`).
struct Carrier {
  bool circle = false;
  Vec2 point, direction;  // line
  double radius = 0;      // circle about `point`
};
// Which of two points was taken (TRC-LOOK-4), from the carriers: the two points lie symmetric about
// an axis (the perpendicular through the circle's centre to the line, the line of centres).
// `first_nearer`: how much nearer to `near` the first of carrier_intersections' points is than
// the second (mm: the distance of `near` from the axis, signed); 0 within fast's error of it, a
// tie, which takes the point further along `ahead`; 0 too for one point.
struct NearerChoice {
  double first_nearer = 0;
  bool second = false;  // the second point is taken
};
bool nearest_intersection(const Carrier& u, const Carrier& v, Vec2 near, Vec2 ahead, Vec2& out,
                          NearerChoice* choice = nullptr);
// That choice between the two points xs of carrier_intersections.
NearerChoice nearer_choice(const Carrier& u, const Carrier& v, const Vec2 xs[2], Vec2 near, Vec2 ahead);
// The same at a programmed corner `corner`, the equidistants' carriers for tool radius `r`, and
// their gap as a margin (TRC-ARC-CORNER-1).
bool corner_intersection(const Carrier& u, const Carrier& v, Vec2 corner, Vec2 ahead, double r, Vec2& out);
double corner_gap(const Carrier& u, const Carrier& v, double r);
// Carriers (one a circle at least) that miss or cross by less than the rounding of their data:
// for the exact data they may touch, and the intersections in double would lie sqrt(u) of the
// size apart; their touching point (TRC-LOOK-2).
bool touching_within_rounding(const Carrier& u, const Carrier& v, Vec2& out);
// How far an intersection x of two carriers may lie from the exact one along them: 64 u of the
// size over the sine of their crossing (PATH-ELEMENT-2).
double intersection_error(const Carrier& u, const Carrier& v, Vec2 x);
// Two line carriers parallel and on one line within the rounding of their data.
bool on_one_line(const Carrier& u, const Carrier& v);
// Two circles within rounding of one circle (the same centre and radius to the doubles' error):
// arcs of one programmed circle, whose equidistants on one side are one circle.
bool on_one_circle(const Carrier& u, const Carrier& v);
// All points common to two carriers (0, 1 or 2; tangency gives one).
int carrier_intersections(const Carrier& u, const Carrier& v, Vec2 out[2]);
// <= 0 when two carriers (at least one a circle) meet: see ref's carrier_gap.
double carrier_gap(const Carrier& u, const Carrier& v);

// The signed rotation in (-pi, pi] from `from` to `to` in the sense `sense`, and the sweep in
// (0, 2 pi] of a circle element.
double signed_rotation(Vec2 from, Vec2 to, int sense);
inline double sweep(const Element& e) { return e.turn; }

// PATH-ELEMENT-2: an arc's end lies in its start's direction from the centre within rounding (u and
// v from the centre to start and end): its points alone cannot tell a sliver from a whole turn.
inline bool turn_undetermined(Vec2 u, Vec2 v) {
  if (!(dot(u, v) > 0)) return false;
  const double c = std::fabs(cross(u, v)), band = 64 * 0x1p-53;
  // (|u| + |v|) max(|u|, |v|) <= 2 (|u|^2 + |v|^2), with a factor 2 to spare: beyond that bound
  // the turn reads without the square roots (almost every corner circle).
  if (c > band * 2 * (dot(u, u) + dot(v, v))) return false;
  double nu = norm(u), nv = norm(v);
  return c <= band * (nu + nv) * std::max(nu, nv);
}

}  // namespace cutcom::fast
