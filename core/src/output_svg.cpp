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
  double min_a = 0, min_b = 0, scale = 1, height = 0, pad = 40, top = 0;
  bool side = false;  // a side view: circles of the plane are drawn as sampled helices
  PlaneAxes plane{0, 1, 2};
  double a(const PathPoint& p) const { return pick(p, axes.abscissa); }
  double b(const PathPoint& p) const { return pick(p, axes.ordinate); }
  static double pick(const PathPoint& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }
  double sx(const PathPoint& p) const { return pad + (a(p) - min_a) * scale; }
  double sy(const PathPoint& p) const { return top + height - pad - (b(p) - min_b) * scale; }
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
    double smx = v.pad + (mx - v.min_a) * v.scale, smy = v.top + v.height - v.pad - (my - v.min_b) * v.scale;
    return fmt::format("M {:.3f} {:.3f} A {:.3f} {:.3f} 0 0 {} {:.3f} {:.3f} A {:.3f} {:.3f} 0 0 {} {:.3f} {:.3f}",
                       v.sx(s), v.sy(s), rs, rs, ccw ? 0 : 1, smx, smy, rs, rs, ccw ? 0 : 1, v.sx(s), v.sy(s));
  }
  double rs = r * v.scale;
  return fmt::format("M {:.3f} {:.3f} A {:.3f} {:.3f} 0 {} {} {:.3f} {:.3f}", v.sx(s), v.sy(s), rs, rs,
                     sweep > M_PI ? 1 : 0, ccw ? 0 : 1, v.sx(e), v.sy(e));
}

// A circle of the plane (a helix if the applicate moves) seen from the side: sampled.
std::string helix_path(const View& v, const PathElement& e) {
  const PlaneAxes& p = v.plane;
  auto at = [&](const PathPoint& q, int i) { return View::pick(q, i); };
  double ca = at(e.center, p.abscissa), cb = at(e.center, p.ordinate);
  double a0 = std::atan2(at(e.start, p.ordinate) - cb, at(e.start, p.abscissa) - ca);
  double a1 = std::atan2(at(e.end, p.ordinate) - cb, at(e.end, p.abscissa) - ca);
  double r = std::hypot(at(e.start, p.ordinate) - cb, at(e.start, p.abscissa) - ca);
  double sweep = e.ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-12) sweep += 2 * M_PI;
  double h0 = at(e.start, p.applicate), h1 = at(e.end, p.applicate);
  std::string d = fmt::format("M {:.3f} {:.3f}", v.sx(e.start), v.sy(e.start));
  const int n = 48;
  for (int k = 1; k <= n; ++k) {
    double f = static_cast<double>(k) / n, ang = a0 + (e.ccw ? 1 : -1) * sweep * f;
    PathPoint q;
    double* c[3] = {&q.x, &q.y, &q.z};
    *c[p.abscissa] = ca + r * std::cos(ang), *c[p.ordinate] = cb + r * std::sin(ang),
    *c[p.applicate] = h0 + (h1 - h0) * f;
    d += fmt::format(" L {:.3f} {:.3f}", v.sx(q), v.sy(q));
  }
  return d;
}

}  // namespace

std::vector<ProgrammedSegment> programmed_contour(const std::vector<Block>& blocks) {
  std::vector<ProgrammedSegment> out;
  bool p4_pending = false;  // SAR-P4-2: the next traversing block's motion is the SAR element
  for (const Block& b : blocks) {
    if (b.is_sar_block()) {  // its contour is generated, not programmed (drawn as path)
      p4_pending = !b.programs_plane_axis() &&
                   (*b.words.sar_contour == SarContour::kG147 || *b.words.sar_contour == SarContour::kG247 ||
                    *b.words.sar_contour == SarContour::kG347);
      continue;
    }
    if (p4_pending && b.moves_in_plane()) {
      p4_pending = false;
      continue;
    }
    if (b.start == b.end && !(b.is_arc() && b.centre)) continue;
    ProgrammedSegment s;
    s.start = {b.start.x.to_double(), b.start.y.to_double(), b.start.z.to_double()};
    s.end = {b.end.x.to_double(), b.end.y.to_double(), b.end.z.to_double()};
    s.rapid = b.state.motion == Motion::kRapid;
    s.line = b.words.line;
    s.label = b.words.number ? fmt::format("N{}", *b.words.number) : fmt::format("L{}", b.words.line);
    if (b.is_arc() && b.centre) {
      s.arc = true;
      s.ccw = b.state.motion == Motion::kArcCcw;
      s.center = {b.centre->x.to_double(), b.centre->y.to_double(), b.centre->z.to_double()};
    }
    out.push_back(s);
  }
  return out;
}

namespace {

// One panel of the picture: the plan view (abscissa, ordinate) or the side view (abscissa,
// applicate) where the path moves along the applicate (SAR infeeds, helices).
void draw_panel(std::ostream& out, const View& v, const std::vector<ProgrammedSegment>& programmed,
                const RunResult& result) {
  for (const auto& s : programmed) {
    if (v.side && s.arc) continue;  // programmed circles are shown in the plan view
    std::string d =
        s.arc ? arc_path(v, s.start, s.end, s.center, s.ccw)
              : fmt::format("M {:.3f} {:.3f} L {:.3f} {:.3f}", v.sx(s.start), v.sy(s.start), v.sx(s.end), v.sy(s.end));
    out << fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#999\" stroke-width=\"2\" stroke-dasharray=\"6 3\"/>\n",
                       d);
  }
  for (const auto& s : programmed)
    out << fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#666\" font-size=\"10\">{}</text>\n", v.sx(s.end) + 3,
                       v.sy(s.end) - 3, s.label);
  for (const auto& e : result.path) {
    std::string d =
        e.type == ElementType::kArc
            ? (v.side ? helix_path(v, e) : arc_path(v, e.start, e.end, e.center, e.ccw))
            : fmt::format("M {:.3f} {:.3f} L {:.3f} {:.3f}", v.sx(e.start), v.sy(e.start), v.sx(e.end), v.sy(e.end));
    const char* colour = e.rapid ? "#d62728" : e.origin.kind == OriginKind::kTransitionCircle ? "#ff8c00" : "#1f5fbf";
    out << fmt::format(
        "<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} marker-end=\"url(#arrow)\">"
        "<title>{}</title></path>\n",
        d, colour, e.rapid ? 1.5 : 2, e.rapid ? " stroke-dasharray=\"4 3\"" : "", describe(e.origin));
  }
  // SAR-VAR-1: $P_APR (P3) and $P_AEP (P4) of each SAR approach.
  for (const auto& var : result.variables)
    for (const auto& [p, name] : {std::pair{var.p_apr, "P3"}, std::pair{var.p_aep, "P4"}})
      out << fmt::format(
          "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"3\" fill=\"#2ca02c\"/><text x=\"{:.1f}\" y=\"{:.1f}\" "
          "fill=\"#2ca02c\" font-size=\"11\">{} L{}</text>\n",
          v.sx(p), v.sy(p), v.sx(p) + 5, v.sy(p) + 14, name, var.line);
}

// The extent of everything drawn in a view, and the scale that fits `width`.
void fit(View& v, const std::vector<ProgrammedSegment>& programmed, const RunResult& result, double width,
         bool arcs_in_view) {
  double lo_a = std::numeric_limits<double>::max(), lo_b = lo_a, hi_a = -lo_a, hi_b = -lo_a;
  auto grow = [&](const PathPoint& p, double r) {
    lo_a = std::min(lo_a, v.a(p) - r), hi_a = std::max(hi_a, v.a(p) + r);
    lo_b = std::min(lo_b, v.b(p) - r), hi_b = std::max(hi_b, v.b(p) + r);
  };
  for (const auto& s : programmed) {
    grow(s.start, 0), grow(s.end, 0);
    if (s.arc && arcs_in_view) grow(s.center, std::hypot(v.a(s.start) - v.a(s.center), v.b(s.start) - v.b(s.center)));
  }
  for (const auto& e : result.path) {
    grow(e.start, 0), grow(e.end, 0);
    if (e.type == ElementType::kArc && arcs_in_view)
      grow(e.center, std::hypot(v.a(e.start) - v.a(e.center), v.b(e.start) - v.b(e.center)));
  }
  if (lo_a > hi_a) lo_a = hi_a = lo_b = hi_b = 0;
  double span = std::max({hi_a - lo_a, hi_b - lo_b, 1e-9});
  v.scale = (width - 2 * v.pad) / span;
  v.min_a = lo_a, v.min_b = lo_b;
  v.height = (hi_b - lo_b) * v.scale + 2 * v.pad;
}

}  // namespace

void write_svg(std::ostream& out, const std::vector<ProgrammedSegment>& programmed, const RunResult& result,
               Plane plane, const std::string& title) {
  const double width = 960, header = 60;
  View v;
  v.axes = plane_axes(plane);
  fit(v, programmed, result, width, true);
  v.top = header;
  // The side view, when anything moves along the applicate: abscissa against applicate, at the
  // plan view's scale.
  bool infeed = false;
  for (const auto& e : result.path)
    infeed = infeed || View::pick(e.start, v.axes.applicate) != View::pick(e.end, v.axes.applicate);
  View side;
  side.axes = {v.axes.abscissa, v.axes.applicate, v.axes.ordinate};
  side.side = true, side.plane = v.axes;
  if (infeed) {
    fit(side, programmed, result, width, false);
    side.scale = v.scale, side.min_a = v.min_a;
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const auto& e : result.path)
      lo = std::min({lo, side.b(e.start), side.b(e.end)}), hi = std::max({hi, side.b(e.start), side.b(e.end)});
    side.min_b = lo;
    side.height = (hi - lo) * side.scale + 2 * side.pad;
    side.top = header + v.height + 20;
  }
  double total = header + v.height + (infeed ? side.height + 40 : 0) + 20;
  const char* names = "XYZ";
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n",
      width, total, width, total);
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
  draw_panel(out, v, programmed, result);
  if (infeed) {
    out << fmt::format("<text x=\"{}\" y=\"{:.0f}\" font-weight=\"bold\">side view {}{} (infeed along {})</text>\n",
                       v.pad, side.top - 4, names[side.axes.abscissa], names[side.axes.ordinate],
                       names[side.axes.ordinate]);
    out << fmt::format("<line x1=\"0\" y1=\"{:.0f}\" x2=\"{:.0f}\" y2=\"{:.0f}\" stroke=\"#ddd\"/>\n", side.top - 20,
                       width, side.top - 20);
    draw_panel(out, side, programmed, result);
  }
  for (const auto& a : result.alarms)
    out << fmt::format("<text x=\"{}\" y=\"{:.0f}\" fill=\"#d62728\" font-weight=\"bold\">ALARM {} {}</text>\n", v.pad,
                       total - 10, a.number, a.text);
  out << "</svg>\n";
}

}  // namespace cutcom
