// The equidistant rules of the straight-line slice, literally, with the number model as a
// template parameter (instantiated with the exact sqrt kernel in engine.cpp).
#pragma once

namespace cutcom::ref {

// TRC-EQ-1: the equidistant of a straight block is the block moved by r along its unit normal,
// to the left for side s = +1 (G41), to the right for s = -1 (G42): p + s r n.
template <class K>
typename K::Point_2 equidistant_point(const typename K::Point_2& p, const typename K::Vector_2& unit_normal,
                                      const typename K::FT& side_radius) {
  return p + unit_normal * side_radius;
}

// TRC-G451-1 / TRC-INNER-1: how much both equidistants are shortened at the corner where they
// intersect: s r tan(phi/2) signed with the turn, phi the deflection angle,
//   tan(phi/2) = |cross| / (|d1||d2| + dot).
// Positive at inner corners (shortening), negative at outer ones (extension, G451).
// Undefined for a reversal (|d1||d2| + dot = 0); callers never ask for it.
template <class K>
typename K::FT corner_trim(const typename K::FT& cross, const typename K::FT& dot, const typename K::FT& length1,
                           const typename K::FT& length2, const typename K::FT& side_radius) {
  return side_radius * cross / (length1 * length2 + dot);
}

// The intersection of the two equidistants: the first one's normal end point moved back by the trim.
template <class K>
typename K::Point_2 corner_intersection(const typename K::Point_2& corner, const typename K::Vector_2& normal1,
                                        const typename K::Vector_2& direction1, const typename K::FT& length1,
                                        const typename K::FT& side_radius, const typename K::FT& trim) {
  return corner + normal1 * side_radius - direction1 * (trim / length1);
}

}  // namespace cutcom::ref
