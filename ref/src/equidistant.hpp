// The equidistant constructions, literally, with the number model as a template parameter
// (instantiated with the exact sqrt kernel in engine.cpp).
#pragma once

#include <optional>
#include <vector>

#include "exact_root.hpp"

namespace cutcom::ref {

// TRC-EQ-1: the point of the equidistant at distance r on side s (+1 left, -1 right) of the
// programmed point p, whose unit left normal is n: p + s r n.
template <class K>
typename K::Point_2 equidistant_point(const typename K::Point_2& p, const typename K::Vector_2& unit_normal,
                                      const typename K::FT& side_radius) {
  return p + unit_normal * side_radius;
}

// TRC-ARC-EQ-1: the equidistant of a circle with radius rho and sense sigma is the concentric
// circle of radius rho - s sigma r (the left side of a ccw circle is its inside).
template <class K>
typename K::FT equidistant_radius(const typename K::FT& radius, int sense, const typename K::FT& side_radius) {
  return radius - side_radius * typename K::FT(sense);
}

// TRC-G451-1 / TRC-INNER-1 for two straight blocks: both equidistants are shortened at the corner
// by the signed trim s r cross / (|d1||d2| + dot) (= +- r tan(phi/2)); positive at inner corners,
// negative at outer ones (extension). Undefined for a reversal; callers never ask for it.
template <class K>
typename K::FT corner_trim(const typename K::FT& cross, const typename K::FT& dot, const typename K::FT& length1,
                           const typename K::FT& length2, const typename K::FT& side_radius) {
  // Not 0 short of a reversal, but nearly 0 near one (a KONT approach along the contour's way back).
  return side_radius * cross / settled_divisor(length1 * length2 + dot);
}

// The intersection of two straight equidistants: the first one's normal end point moved back by the trim.
template <class K>
typename K::Point_2 corner_intersection(const typename K::Point_2& corner, const typename K::Vector_2& normal1,
                                        const typename K::Vector_2& direction1, const typename K::FT& length1,
                                        const typename K::FT& side_radius, const typename K::FT& trim) {
  return corner + normal1 * side_radius - direction1 * (trim / length1);
}

// An equidistant extended to its whole carrier: a line (point, direction) or a circle.
template <class K>
struct Carrier {
  bool circle = false;
  typename K::Point_2 point;       // line: a point on it; circle: the centre
  typename K::Vector_2 direction;  // line only
  typename K::FT radius;           // circle only (> 0)
};

// How far apart two carriers are, at least one a circle: <= 0 exactly when they meet (the
// margin of TRC-ARC-CORNER-1 and TRC-LOOK-2). Line and circle: distance of the centre from the
// line less the radius; two circles: the larger of |C1C2| - (R1 + R2) and |R1 - R2| - |C1C2|.
template <class K>
typename K::FT carrier_gap(const Carrier<K>& u, const Carrier<K>& v) {
  using KFT = typename K::FT;
  if (u.circle != v.circle) {
    const Carrier<K>& l = u.circle ? v : u;
    const Carrier<K>& c = u.circle ? u : v;
    KFT cross = l.direction.x() * (c.point.y() - l.point.y()) - l.direction.y() * (c.point.x() - l.point.x());
    return CGAL::abs(cross) / exact_root(l.direction.squared_length()) - c.radius;
  }
  KFT d = exact_root((v.point - u.point).squared_length());
  KFT outside = d - (u.radius + v.radius), inside = CGAL::abs(u.radius - v.radius) - d;
  return CGAL::compare(outside, inside) == CGAL::LARGER ? outside : inside;
}

// Points common to two carriers (0, 1 or 2; tangency gives one).
template <class K>
std::vector<typename K::Point_2> carrier_intersections(const Carrier<K>& u, const Carrier<K>& v) {
  using KFT = typename K::FT;
  using KPoint = typename K::Point_2;
  using KVector = typename K::Vector_2;
  std::vector<KPoint> out;
  if (!u.circle && !v.circle) {
    KFT den = u.direction.x() * v.direction.y() - u.direction.y() * v.direction.x();
    if (CGAL::sign(den) == CGAL::ZERO) return out;  // parallel
    KVector w = v.point - u.point;
    KFT t = (w.x() * v.direction.y() - w.y() * v.direction.x()) / den;
    out.push_back(u.point + u.direction * t);
    return out;
  }
  if (u.circle != v.circle) {
    const Carrier<K>& l = u.circle ? v : u;
    const Carrier<K>& c = u.circle ? u : v;
    // |p + t d - c|^2 = R^2:  a t^2 + 2 b t + k = 0
    KVector pc = l.point - c.point;
    KFT a = l.direction.squared_length();
    KFT b = l.direction * pc;
    KFT k = pc.squared_length() - c.radius * c.radius;
    KFT disc = b * b - a * k;
    CGAL::Sign s = CGAL::sign(disc);
    if (s == CGAL::NEGATIVE) return out;
    if (s == CGAL::ZERO) {
      out.push_back(l.point + l.direction * (-b / a));
      return out;
    }
    KFT root = exact_root(disc);
    out.push_back(l.point + l.direction * ((-b - root) / a));
    out.push_back(l.point + l.direction * ((-b + root) / a));
    return out;
  }
  // Two circles: along the line of centres at m, across by +- h.
  KVector d = v.point - u.point;
  KFT dd = d.squared_length();
  if (CGAL::sign(dd) == CGAL::ZERO) return out;  // concentric
  KFT along = (u.radius * u.radius - v.radius * v.radius + dd) / (KFT(2) * dd);
  KFT across2 = u.radius * u.radius / dd - along * along;
  CGAL::Sign s = CGAL::sign(across2);
  if (s == CGAL::NEGATIVE) return out;
  KPoint m = u.point + d * along;
  KVector perp(-d.y(), d.x());
  if (s == CGAL::ZERO) {
    out.push_back(m);
    return out;
  }
  KFT h = exact_root(across2);
  out.push_back(m + perp * h);
  out.push_back(m - perp * h);
  return out;
}

// Of two distinct intersections (xs[0], xs[1] as carrier_intersections gives them, one carrier at
// least a circle), the sign of |xs[1] - p|^2 - |xs[0] - p|^2 and of (xs[1] - xs[0]) . w, from the
// carriers without the square root: the same signs as the points', far cheaper to decide exactly.
// Line p_l + t d and circle about c: t1 - t0 = 2 root / a > 0 and t1 + t0 = -2b / a, so the first
// difference is (4 root / a)((p_l - p) . d - b) = (4 root / a)((c - p) . d), the second (t1 - t0) d . w.
// Two circles: xs = m -+ h perp (h > 0), m - u.point along d, perp . d = 0: the first difference is
// -4 h (u.point - p) . perp, the second -2 h perp . w.
template <class K>
CGAL::Sign second_farther(const Carrier<K>& u, const Carrier<K>& v, const typename K::Point_2& p) {
  if (u.circle != v.circle) {
    const Carrier<K>& l = u.circle ? v : u;
    const Carrier<K>& c = u.circle ? u : v;
    return CGAL::sign((c.point - p) * l.direction);
  }
  typename K::Vector_2 d = v.point - u.point, perp(-d.y(), d.x());
  return -CGAL::sign((u.point - p) * perp);
}
template <class K>
CGAL::Sign second_ahead(const Carrier<K>& u, const Carrier<K>& v, const typename K::Vector_2& w) {
  if (u.circle != v.circle) return CGAL::sign((u.circle ? v : u).direction * w);
  typename K::Vector_2 d = v.point - u.point, perp(-d.y(), d.x());
  return -CGAL::sign(perp * w);
}

// TRC-LOOK-4's measure: how much nearer to p the first of the two intersections is than the
// second (mm; 0 equally near): the distance of p from the points' axis of symmetry (the
// perpendicular through the circle's centre to the line, the line of centres), signed. Half the
// difference of the squared distances over the chord, without the points: second_farther's
// algebra divided by the length of l.direction, of d.
template <class K>
typename K::FT first_nearer_by(const Carrier<K>& u, const Carrier<K>& v, const typename K::Point_2& p) {
  if (u.circle != v.circle) {
    const Carrier<K>& l = u.circle ? v : u;
    const Carrier<K>& c = u.circle ? u : v;
    return ((c.point - p) * l.direction) / exact_root(l.direction.squared_length());
  }
  typename K::Vector_2 d = v.point - u.point, perp(-d.y(), d.x());
  return ((p - u.point) * perp) / exact_root(d.squared_length());
}

}  // namespace cutcom::ref
