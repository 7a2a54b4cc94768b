// The plane geometry of contour definitions (NC-CONTOUR-*), on interval enclosures (NC-GRID-1):
// the reader computes inserted roundings and chamfers, corners of angle definitions and circle
// centres here, once, and hands both engines decimals.
#pragma once

#include <optional>
#include <string>

#include "cutcom/block.hpp"
#include "grid_value.hpp"

namespace cutcom::contour {

using grid::Interval;

struct IPoint {
  Interval a, o;  // abscissa and ordinate of the plane
};
IPoint in_plane(const Point3& p, PlaneAxes ax);
IPoint operator+(const IPoint& p, const IPoint& q);
IPoint operator-(const IPoint& p, const IPoint& q);
IPoint operator*(const Interval& k, const IPoint& p);
Interval dot(const IPoint& p, const IPoint& q);
Interval cross(const IPoint& p, const IPoint& q);
IPoint perp(const IPoint& p);                     // turned by +90°
IPoint turned(const IPoint& p, Decimal degrees);  // turned counter-clockwise (NC-GRID-1 sines)
Interval norm(const IPoint& p);

// A programmed element of the plane: a line, or a circle (centre per ARC-CENTRE-1 / ARC-CR-1).
struct Element {
  bool arc = false;
  IPoint start, end, centre;
  int sense = 1;  // +1 counter-clockwise
  bool full = false;
  Interval radius;
  IPoint tangent_at_start() const;
  IPoint tangent_at_end() const;
};
// Throws ContourError if the block's circle cannot be built (CR chord too long).
Element element_of(const Block& b);

struct ContourError {
  std::string what;
};

// What the reader inserts at a corner (NC-CONTOUR-1/2): new end of the first element, new start of
// the second, and the inserted element between them.
struct CornerCut {
  IPoint t1, t2;
  bool arc = false;
  IPoint centre;
  int sense = 1;
  Interval value;        // the radius, leg (CHR) or length (CHF) inserted
  bool reduced = false;  // smaller than programmed: the programmed one does not fit
};
enum class CornerKind { kRounding, kChamferLength /*CHF*/, kChamferLeg /*CHR*/ };
// nullopt: the elements meet tangentially (nothing to insert). A value too large for the elements
// is reduced to the largest that fits. Throws ContourError if the contour reverses or no cut fits.
std::optional<CornerCut> cut_corner(const Element& e1, const Element& e2, CornerKind kind, const Interval& value);

// The sweep from `from` to `to` on a circle about `c` in direction `sense`, in [0, 2π).
Interval sweep(const IPoint& c, const IPoint& from, const IPoint& to, int sense);

}  // namespace cutcom::contour
