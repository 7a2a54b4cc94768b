// PROP-CD-1: the clearance of ref's compensated path from the programmed contour, decided exactly.
#include <fmt/format.h>

#include <sstream>

#include "circle_position.hpp"
#include "cutcom/ref/exact_checks.hpp"
#include "exact_path.hpp"
#include "exact_root.hpp"

namespace cutcom::ref {

namespace {

using Segment = Kernel::Segment_2;

// Is the direction v within the circle piece from a to b (about c, sense `sense`; a full turn
// when a = b)?
bool within(const Point& c, const Point& a, const Point& b, int sense, const Vector& v) {
  if (a == b) return true;
  CircleFrame f(a - c, sense);
  return f.compare(f.at(v), f.at(b - c)) != CGAL::POSITIVE;
}

// At least `r` between a circular piece (about c, radius rho, from a to b) and segment pq? The
// minimum is 0 where they cross, else taken at the arc's ends, at the radial projection of p or
// q, or where the circle's normal is the segment's.
bool arc_clear(const Point& c, const FT& rho, const Point& a, const Point& b, int sense, const Segment& pq,
               const FT& r) {
  FT r2 = r * r;
  if (CGAL::compare(CGAL::squared_distance(a, pq), r2) == CGAL::SMALLER) return false;
  if (CGAL::compare(CGAL::squared_distance(b, pq), r2) == CGAL::SMALLER) return false;
  for (const Point& q : {pq.source(), pq.target()}) {
    if (q == c) continue;
    FT gap = exact_root(CGAL::squared_distance(q, c)) - rho;
    if (within(c, a, b, sense, q - c) && CGAL::compare(gap * gap, r2) == CGAL::SMALLER) return false;
  }
  Vector d = pq.target() - pq.source();
  FT length = exact_root(d.squared_length());
  Vector n(-d.y() / length, d.x() / length);
  for (int k : {1, -1}) {
    Point u = c + n * (FT(k) * rho);
    FT t = (u - pq.source()) * d;  // the foot of u lies on pq for 0 <= t <= |d|^2
    if (!within(c, a, b, sense, u - c) || CGAL::sign(t) == CGAL::NEGATIVE ||
        CGAL::compare(t, d.squared_length()) == CGAL::LARGER)
      continue;
    if (CGAL::compare(CGAL::squared_distance(u, pq.supporting_line()), r2) == CGAL::SMALLER) return false;
  }
  // Crossing: the circle meets the segment's line at points on both pieces.
  FT dist = CGAL::abs(CGAL::determinant(d, c - pq.source())) / length;
  if (CGAL::compare(dist, rho) == CGAL::LARGER) return true;
  FT foot = (c - pq.source()) * d / length, half = exact_root(rho * rho - dist * dist);
  for (int k : {1, -1}) {
    FT t = foot + FT(k) * half;
    if (CGAL::sign(t) == CGAL::NEGATIVE || CGAL::compare(t, length) == CGAL::LARGER) continue;
    Point x = pq.source() + d * (t / length);
    if (within(c, a, b, sense, x - c)) return false;
  }
  return true;
}

}  // namespace

ClearanceCheck exact_clearance(const std::string& program, const MachineData& md) {
  ClearanceCheck out;
  std::istringstream in(program);
  ProgramReader reader(in, md.initial_state());
  CollectingSink sink;
  ExactPath path;
  try {
    run_exact(reader, md, sink, path);
  } catch (const UnsupportedError&) {  // TRC-UNSUP-1: nothing to check
    out.unsupported = true;
    return out;
  }
  out.alarm = !sink.result.alarms.empty();
  if (out.alarm) return out;
  // The programmed contour: compensated blocks with motion in the plane after the selection block.
  std::istringstream again(program);
  ProgramReader blocks(again, md.initial_state());
  std::vector<Segment> contour;
  std::vector<int> lines;
  Block b;
  Side before = Side::kOff;
  std::uint32_t selection = 0;
  PlaneAxes axes{0, 1, 2};
  while (blocks.next(b)) {
    bool compensated = b.state.side != Side::kOff && !selects_anew(b.state, before, selection);
    before = b.state.side, selection = b.state.selection;
    if (!compensated || !b.moves_in_plane()) continue;
    if (b.is_arc()) return out;  // straight contours only
    axes = plane_axes(b.state.plane);
    contour.emplace_back(plane_point(b.start, axes), plane_point(b.end, axes));
    lines.push_back(b.words.line);
  }
  const std::vector<ExactPath::Element>& elements = path.elements();
  if (elements.size() != sink.result.path.size()) {
    out.violation = "exact and output paths differ in length";
    return out;
  }
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const PathElement& shown = sink.result.path[i];
    if (shown.origin.kind != OriginKind::kOffset && shown.origin.kind != OriginKind::kTransitionCircle) continue;
    const ExactPath::Element& e = elements[i];
    FT r = CGAL::abs(e.side_radius);  // s r for equidistants and transition circles alike
    Point a = e.start.plane(e.axes), z = e.end.plane(e.axes);
    for (std::size_t k = 0; k < contour.size(); ++k) {
      ++out.pairs;
      bool clear;
      if (shown.type == ElementType::kLine) {
        clear = a == z ? CGAL::compare(CGAL::squared_distance(a, contour[k]), r * r) != CGAL::SMALLER
                       : CGAL::compare(CGAL::squared_distance(Segment(a, z), contour[k]), r * r) != CGAL::SMALLER;
      } else {
        clear = arc_clear(e.centre->plane(e.axes), r, a, z, shown.ccw ? 1 : -1, contour[k], r);
      }
      if (!clear) {
        out.violation = fmt::format("element {} ({}) comes closer than r to the block of line {}", i,
                                    describe(shown.origin), lines[k]);
        return out;
      }
    }
  }
  return out;
}

}  // namespace cutcom::ref
