// fast's double-precision plane geometry: vectors in (abscissa, ordinate) of the active plane.
#pragma once

#include <cmath>

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
inline double norm(Vec2 p) { return std::hypot(p.a, p.b); }

// A straight compensated block in plane coordinates.
struct LineSegment {
  Vec2 start, end;
  Vec2 unit;      // direction of travel, |unit| = 1
  double length;  // > 0 (blocks without motion in the plane never become segments)
  static LineSegment between(Vec2 s, Vec2 e) {
    LineSegment l;
    l.start = s, l.end = e;
    Vec2 d = e - s;
    l.length = norm(d);
    l.unit = (1.0 / l.length) * d;
    return l;
  }
  // TRC-EQ-1: point of the equidistant at distance r on side s (+1 left, -1 right) of point p.
  Vec2 offset(Vec2 p, double sr) const { return p + sr * left_normal(unit); }
};

// The corner between two consecutive segments, seen from side s.
struct Corner {
  enum class Kind { kTangent, kInner, kOuter, kReversal } kind;
  double sine;    // s * sin(deflection): > 0 inner, < 0 outer (the TRC-CORNER-1 margin)
  double cosine;  // cos(deflection)
  double trim;    // signed shortening of both equidistants at the corner (< 0: extension, G451)
};

Corner classify_corner(const LineSegment& first, const LineSegment& second, int side, double radius);

}  // namespace cutcom::fast
