#include "exact_path.hpp"

#include <fmt/format.h>

#include "exact_root.hpp"

namespace cutcom::ref {

ExactPoint ExactPoint::in_plane(const Point& p, const Decimal& applicate, PlaneAxes axes) {
  ExactPoint e;
  FT* c[3] = {&e.x, &e.y, &e.z};
  *c[axes.abscissa] = p.x();
  *c[axes.ordinate] = p.y();
  *c[axes.applicate] = leaf(applicate);
  return e;
}

Point ExactPoint::plane(PlaneAxes axes) const {
  const FT* c[3] = {&x, &y, &z};
  return Point(*c[axes.abscissa], *c[axes.ordinate]);
}

PathPoint ExactPath::output(const ExactPoint& p) const {
  return {nearest_mm(p.x), nearest_mm(p.y), nearest_mm(p.z)};  // the output boundary
}

bool ExactPath::same(const ExactPoint& a, const ExactPoint& b) const { return a.x == b.x && a.y == b.y && a.z == b.z; }

FT ExactPath::distance(const ExactPoint& a, const ExactPoint& b) const {
  FT dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
  return exact_root(dx * dx + dy * dy + dz * dz);
}

ExactPath::Element ExactPath::line_element(int line, const ExactPoint& from, const ExactPoint& to,
                                           const ContourElement* offset_of, const FT& side_radius, PlaneAxes axes) {
  Element e{line, from, to, axes, std::nullopt, std::nullopt, side_radius};
  if (offset_of) e.offset_of = *offset_of;
  return e;
}

ExactPath::Element ExactPath::circle_element(int line, const ExactPoint& from, const ExactPoint& to,
                                             const ExactPoint& centre, const FT& side_radius, PlaneAxes axes) {
  return Element{line, from, to, axes, std::nullopt, centre, side_radius};
}

void ExactPath::check(ExactCheckReport& report) const {
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const Element& e = elements_[i];
    if (e.offset_of) {
      // PROP-EXACT-1 (TRC-EQ-1): cross(d, P - A) = s r |d| for both end points.
      const ContourElement& l = *e.offset_of;
      for (const ExactPoint* p : {&e.start, &e.end}) {
        ++report.offset_endpoints_checked;
        if (CGAL::determinant(l.d, p->plane(e.axes) - l.a) != e.side_radius * l.length)
          report.failures.push_back(
              fmt::format("offset element {} of line {}: end point not at distance r", i, l.line));
      }
    }
    if (e.centre) {
      // PROP-EXACT-2 (TRC-G450-1, TRC-ARC-EQ-1): both ends at the element's radius from its centre
      // (the programmed corner for a transition circle, the programmed centre for an equidistant).
      ++report.circles_checked;
      FT r2 = e.side_radius * e.side_radius;
      Point c = e.centre->plane(e.axes);
      if (CGAL::squared_distance(e.start.plane(e.axes), c) != r2 ||
          CGAL::squared_distance(e.end.plane(e.axes), c) != r2)
        report.failures.push_back(fmt::format("transition circle {}: end point not at distance r", i));
    }
    if (i > 0) {
      // PROP-EXACT-3 (PATH-CONT-1): the path is continuous.
      ++report.joints_checked;
      if (!same(elements_[i - 1].end, e.start)) report.failures.push_back(fmt::format("gap before element {}", i));
    }
  }
}

}  // namespace cutcom::ref
