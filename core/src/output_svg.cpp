// A picture a person can read: programmed contour (grey), tool-centre path (blue feed, red dashed
// rapid, orange transition circles), tool circles at the element ends, block labels.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cutcom/output.hpp"

namespace cutcom {

namespace {

struct View {
  PlaneAxes axes;
  double min_a = 0, min_b = 0, scale = 1, height = 0, pad = 40;
  double a(const PathPoint& p) const { return pick(p, axes.abscissa); }
  double b(const PathPoint& p) const { return pick(p, axes.ordinate); }
  static double pick(const PathPoint& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }
  double sx(const PathPoint& p) const { return pad + (a(p) - min_a) * scale; }
  double sy(const PathPoint& p) const { return height - pad - (b(p) - min_b) * scale; }
};

std::string arc_path(const View& v, const PathPoint& s, const PathPoint& e, const PathPoint& c, bool ccw) {
  double r = std::hypot(v.a(s) - v.a(c), v.b(s) - v.b(c));
  double a0 = std::atan2(v.b(s) - v.b(c), v.a(s) - v.a(c));
  double a1 = std::atan2(v.b(e) - v.b(c), v.a(e) - v.a(c));
  double sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 0) sweep += 2 * M_PI;
  if (std::hypot(v.a(s) - v.a(e), v.b(s) - v.b(e)) < 1e-12 * std::max(1.0, r)) {
    // Full circle: two half arcs.
    double mx = 2 * v.a(c) - v.a(s), my = 2 * v.b(c) - v.b(s);
    double rs = r * v.scale;
    double smx = v.pad + (mx - v.min_a) * v.scale, smy = v.height - v.pad - (my - v.min_b) * v.scale;
    return fmt::format("M {:.3f} {:.3f} A {:.3f} {:.3f} 0 0 {} {:.3f} {:.3f} A {:.3f} {:.3f} 0 0 {} {:.3f} {:.3f}",
                       v.sx(s), v.sy(s), rs, rs, ccw ? 0 : 1, smx, smy, rs, rs, ccw ? 0 : 1, v.sx(s), v.sy(s));
  }
  double rs = r * v.scale;
  return fmt::format("M {:.3f} {:.3f} A {:.3f} {:.3f} 0 {} {} {:.3f} {:.3f}", v.sx(s), v.sy(s), rs, rs,
                     sweep > M_PI ? 1 : 0, ccw ? 0 : 1, v.sx(e), v.sy(e));
}

}  // namespace

std::vector<ProgrammedSegment> programmed_contour(const std::vector<Block>& blocks) {
  std::vector<ProgrammedSegment> out;
  for (const Block& b : blocks) {
    if (b.start == b.end && !(b.is_arc() && b.centre)) continue;
    ProgrammedSegment s;
    s.start = {b.start.x.to_double(), b.start.y.to_double(), b.start.z.to_double()};
    s.end = {b.end.x.to_double(), b.end.y.to_double(), b.end.z.to_double()};
    s.rapid = b.state.motion == Motion::kRapid;
    s.line = b.words.line;
    if (b.is_arc() && b.centre) {
      s.arc = true;
      s.ccw = b.state.motion == Motion::kArcCcw;
      s.center = {b.centre->x.to_double(), b.centre->y.to_double(), b.centre->z.to_double()};
    }
    out.push_back(s);
  }
  return out;
}

void write_svg(std::ostream& out, const std::vector<ProgrammedSegment>& programmed, const RunResult& result,
               Plane plane, const std::string& title) {
  View v;
  v.axes = plane_axes(plane);
  double lo_a = std::numeric_limits<double>::max(), lo_b = lo_a, hi_a = -lo_a, hi_b = -lo_a;
  auto grow = [&](const PathPoint& p, double r) {
    lo_a = std::min(lo_a, v.a(p) - r), hi_a = std::max(hi_a, v.a(p) + r);
    lo_b = std::min(lo_b, v.b(p) - r), hi_b = std::max(hi_b, v.b(p) + r);
  };
  for (const auto& s : programmed) grow(s.start, 0), grow(s.end, 0);
  for (const auto& e : result.path) {
    grow(e.start, 0), grow(e.end, 0);
    if (e.type == ElementType::kArc)
      grow(e.center, std::hypot(v.a(e.start) - v.a(e.center), v.b(e.start) - v.b(e.center)));
  }
  if (lo_a > hi_a) lo_a = hi_a = lo_b = hi_b = 0;
  double span = std::max({hi_a - lo_a, hi_b - lo_b, 1e-9});
  double width = 960;
  v.scale = (width - 2 * v.pad) / span;
  v.min_a = lo_a, v.min_b = lo_b;
  v.height = (hi_b - lo_b) * v.scale + 2 * v.pad + 60;
  const char* names = "XYZ";
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n",
      width, v.height, width, v.height);
  out << "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
         "orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"context-stroke\"/></marker></defs>\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << fmt::format("<text x=\"{}\" y=\"18\" font-size=\"14\" font-weight=\"bold\">{}</text>\n", v.pad, title);
  out << fmt::format(
      "<g transform=\"translate({},{})\"><line x1=\"0\" y1=\"0\" x2=\"24\" y2=\"0\" stroke=\"#999\" stroke-width=\"2\" "
      "stroke-dasharray=\"6 3\"/><text x=\"30\" y=\"4\">programmed contour</text>"
      "<line x1=\"170\" y1=\"0\" x2=\"194\" y2=\"0\" stroke=\"#1f5fbf\" stroke-width=\"2\"/><text x=\"200\" "
      "y=\"4\">tool "
      "centre, feed</text>"
      "<line x1=\"330\" y1=\"0\" x2=\"354\" y2=\"0\" stroke=\"#d62728\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\"/>"
      "<text x=\"360\" y=\"4\">rapid</text>"
      "<line x1=\"420\" y1=\"0\" x2=\"444\" y2=\"0\" stroke=\"#ff8c00\" stroke-width=\"2.5\"/><text x=\"450\" y=\"4\">"
      "transition circle</text><text x=\"580\" y=\"4\">plane {}{} (scale {:.3g} px/mm)</text></g>\n",
      v.pad, 38, names[v.axes.abscissa], names[v.axes.ordinate], v.scale);
  for (const auto& s : programmed) {
    std::string d =
        s.arc ? arc_path(v, s.start, s.end, s.center, s.ccw)
              : fmt::format("M {:.3f} {:.3f} L {:.3f} {:.3f}", v.sx(s.start), v.sy(s.start), v.sx(s.end), v.sy(s.end));
    out << fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#999\" stroke-width=\"2\" stroke-dasharray=\"6 3\"/>\n",
                       d);
  }
  for (const auto& s : programmed)
    out << fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#666\" font-size=\"10\">L{}</text>\n", v.sx(s.end) + 3,
                       v.sy(s.end) - 3, s.line);
  for (const auto& e : result.path) {
    std::string d = e.type == ElementType::kArc ? arc_path(v, e.start, e.end, e.center, e.ccw)
                                                : fmt::format("M {:.3f} {:.3f} L {:.3f} {:.3f}", v.sx(e.start),
                                                              v.sy(e.start), v.sx(e.end), v.sy(e.end));
    const char* colour = e.rapid ? "#d62728" : e.origin.kind == OriginKind::kTransitionCircle ? "#ff8c00" : "#1f5fbf";
    out << fmt::format(
        "<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} marker-end=\"url(#arrow)\">"
        "<title>{}</title></path>\n",
        d, colour, e.rapid ? 1.5 : 2, e.rapid ? " stroke-dasharray=\"4 3\"" : "", describe(e.origin));
  }
  for (const auto& a : result.alarms)
    out << fmt::format("<text x=\"{}\" y=\"{:.0f}\" fill=\"#d62728\" font-weight=\"bold\">ALARM {} {}</text>\n", v.pad,
                       v.height - 10, a.number, a.text);
  out << "</svg>\n";
}

}  // namespace cutcom
