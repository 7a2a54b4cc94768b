// A picture a person can read: programmed contour (grey), tool-centre path (blue feed, red dashed
// rapid, orange transition circles), block labels. Memory is bounded whatever the program length
// (issue "Performance" item 6): past PictureLimits::full_elements the picture keeps polylines,
// simplified within a stated bound (Sketch below), instead of every element.
#include <fmt/format.h>

#include <algorithm>
#include <array>
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

// A circle of a plane (a helix if the applicate moves), as points along it.
struct PlaneArc {
  PlaneAxes p;
  double ca, cb, a0, r, sweep, h0, h1;
  bool ccw;
  PlaneArc(const PathPoint& s, const PathPoint& e, const PathPoint& centre, bool counter, PlaneAxes axes)
      : p(axes), ccw(counter) {
    auto at = View::pick;
    ca = at(centre, p.abscissa), cb = at(centre, p.ordinate);
    a0 = std::atan2(at(s, p.ordinate) - cb, at(s, p.abscissa) - ca);
    double a1 = std::atan2(at(e, p.ordinate) - cb, at(e, p.abscissa) - ca);
    r = std::hypot(at(s, p.ordinate) - cb, at(s, p.abscissa) - ca);
    sweep = ccw ? a1 - a0 : a0 - a1;
    while (sweep <= 1e-12) sweep += 2 * M_PI;
    h0 = at(s, p.applicate), h1 = at(e, p.applicate);
  }
  PathPoint at(double f) const {  // f in [0, 1] of the sweep
    double ang = a0 + (ccw ? 1 : -1) * sweep * f;
    PathPoint q;
    double* c[3] = {&q.x, &q.y, &q.z};
    *c[p.abscissa] = ca + r * std::cos(ang), *c[p.ordinate] = cb + r * std::sin(ang),
    *c[p.applicate] = h0 + (h1 - h0) * f;
    return q;
  }
};

// A circle of the plane (a helix if the applicate moves) seen from the side: sampled.
std::string helix_path(const View& v, const PathElement& e) {
  PlaneArc arc(e.start, e.end, e.center, e.ccw, v.plane);
  std::string d = fmt::format("M {:.3f} {:.3f}", v.sx(e.start), v.sy(e.start));
  const int n = 48;
  for (int k = 1; k <= n; ++k) {
    PathPoint q = arc.at(static_cast<double>(k) / n);
    d += fmt::format(" L {:.3f} {:.3f}", v.sx(q), v.sy(q));
  }
  return d;
}

}  // namespace

// The programmed contour, block by block (the SAR contour is generated, so drawn as path).
std::optional<ProgrammedSegment> ProgrammedContour::add(const Block& b) {
  if (b.is_sar_block()) {  // its contour is generated, not programmed (drawn as path)
    p4_pending_ = !b.programs_plane_axis() &&
                  (*b.words.sar_contour == SarContour::kG147 || *b.words.sar_contour == SarContour::kG247 ||
                   *b.words.sar_contour == SarContour::kG347);
    return std::nullopt;
  }
  if (p4_pending_ && b.moves_in_plane()) {  // SAR-P4-2: the next traversing block's motion is the SAR element
    p4_pending_ = false;
    return std::nullopt;
  }
  // TOOL-TURN-1: the contour as programmed, without the turning tool's tip offset.
  auto programmed = [](Point3 p, const Point3& shift) {
    for (int axis = 0; axis < 3; ++axis) coord(p, axis) = coord(p, axis) - coord(shift, axis);
    return p;
  };
  auto drawn = [](const Point3& p) { return PathPoint{p.x.to_double(), p.y.to_double(), p.z.to_double()}; };
  Point3 start = programmed(b.start, b.tip_shift_start), end = programmed(b.end, b.tip_shift_end);
  if (start == end && !(b.is_arc() && b.centre)) return std::nullopt;
  ProgrammedSegment s;
  s.start = drawn(start);
  s.end = drawn(end);
  s.rapid = b.state.motion == Motion::kRapid;
  s.line = b.words.line;
  s.label = b.words.number ? fmt::format("N{}", *b.words.number) : fmt::format("L{}", b.words.line);
  if (b.is_arc() && b.centre) {
    s.arc = true;
    s.ccw = b.state.motion == Motion::kArcCcw;
    s.center = drawn(programmed(*b.centre, b.tip_shift_end));
  }
  return s;
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

namespace {

// What a picture keeps once it holds more than PictureLimits::full_elements: polylines per style,
// each point within `bound()` of the exact path. A new point replaces the last one while the
// points it passes over stay within `tau` of the chord (at most kSkipped of them are remembered);
// when the polylines hold more than the limit, `tau` doubles and every polyline is simplified
// again. Sampling an arc (sagitta at most tau) and each pass add at most the pass's tau, so the
// total stays within 2 * tau (tau0 + tau0 + 2 tau0 + … + tau = 2 tau).
enum class Style : std::uint8_t { kProgrammed, kFeed, kRapid };

struct Sketch {
  struct Stroke {
    Style style;
    std::vector<PathPoint> points;
  };
  static constexpr std::size_t kSkipped = 64;
  std::vector<Stroke> strokes;
  std::array<int, 2> open{-1, -1};  // the stroke being extended, per channel (programmed, path)
  std::array<std::vector<PathPoint>, 2> skipped;
  std::size_t points = 0, limit = 0;
  double tau = 0;

  static bool same(const PathPoint& a, const PathPoint& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
  static double distance_to_segment(const PathPoint& p, const PathPoint& a, const PathPoint& b) {
    double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    double wx = p.x - a.x, wy = p.y - a.y, wz = p.z - a.z;
    double uu = ux * ux + uy * uy + uz * uz;
    double t = uu > 0 ? std::clamp((wx * ux + wy * uy + wz * uz) / uu, 0.0, 1.0) : 0.0;
    return std::hypot(wx - t * ux, wy - t * uy, wz - t * uz);
  }
  // Appends p to `s`, replacing its last point where the points passed over stay within tau.
  bool extend(std::vector<PathPoint>& s, std::vector<PathPoint>& passed, const PathPoint& p) const {
    if (s.size() >= 2 && passed.size() < kSkipped) {
      const PathPoint& a = s[s.size() - 2];
      bool within = distance_to_segment(s.back(), a, p) <= tau;
      for (const PathPoint& q : passed) within = within && distance_to_segment(q, a, p) <= tau;
      if (within) {
        passed.push_back(s.back());
        s.back() = p;
        return false;
      }
    }
    passed.clear();
    s.push_back(p);
    return true;
  }
  void add_point(int channel, Style style, const PathPoint& start, const PathPoint& p) {
    auto c = static_cast<std::size_t>(channel);
    int& o = open[c];
    if (o < 0 || strokes[static_cast<std::size_t>(o)].style != style ||
        !same(strokes[static_cast<std::size_t>(o)].points.back(), start)) {
      strokes.push_back({style, {start}});
      o = static_cast<int>(strokes.size()) - 1;
      skipped[c].clear();
      ++points;
    }
    if (extend(strokes[static_cast<std::size_t>(o)].points, skipped[c], p)) ++points;
    if (points > limit) simplify_again();
  }
  void add(int channel, Style style, const PathPoint& s, const PathPoint& e, const PathPoint* centre, bool ccw,
           Plane plane) {
    if (!centre) return add_point(channel, style, s, e);
    // An arc of the plane (a helix if the applicate moves): points whose chords stay within tau.
    PlaneArc arc(s, e, *centre, ccw, plane_axes(plane));
    double step = arc.r > tau ? 2 * std::acos(1 - tau / arc.r) : arc.sweep;
    int n = static_cast<int>(std::clamp(std::ceil(arc.sweep / std::max(step, 1e-9)), 1.0, 4096.0));
    PathPoint from = s;
    for (int k = 1; k <= n; ++k) {
      PathPoint q = k < n ? arc.at(static_cast<double>(k) / n) : e;
      add_point(channel, style, from, q);
      from = strokes[static_cast<std::size_t>(open[static_cast<std::size_t>(channel)])].points.back();
    }
  }
  void simplify_again() {
    while (points > limit) {
      tau *= 2;
      points = 0;
      for (Stroke& st : strokes) {
        std::vector<PathPoint> kept{st.points.front()}, passed;
        for (std::size_t k = 1; k < st.points.size(); ++k) extend(kept, passed, st.points[k]);
        st.points = std::move(kept);
        points += st.points.size();
      }
      skipped[0].clear(), skipped[1].clear();
      if (tau > 1e12) break;  // nothing left to simplify
    }
  }
  double bound() const { return 2 * tau; }
};

}  // namespace

struct SvgPicture::Impl {
  PictureLimits limits;
  Plane plane = Plane::kG17;  // the picture's plane: arcs of the path turn in it
  ProgrammedContour contour;
  // Full detail, up to the limit.
  std::vector<ProgrammedSegment> programmed;
  RunResult result;  // path elements, alarms and SAR variables only
  // Past it: polylines.
  bool reduced = false;
  Sketch sketch;
  std::vector<std::pair<PathPoint, std::string>> labels;  // every label_stride-th block's label
  std::size_t label_stride = 1, label_count = 0, elements = 0, segments = 0;
  std::size_t markers_dropped = 0;
  std::array<bool, 3> moved{false, false, false};  // an element moved along X, Y, Z
  std::vector<Plane> planes;                       // per programmed segment while in full detail

  void label(const ProgrammedSegment& s) {
    if (label_count++ % label_stride != 0) return;
    labels.emplace_back(s.end, s.label);
    if (labels.size() <= limits.labels) return;
    label_stride *= 2;  // keep every other one of those kept
    std::size_t w = 0;
    for (std::size_t k = 0; k < labels.size(); k += 2) labels[w++] = std::move(labels[k]);
    labels.resize(w);
  }
  void reduce() {  // full detail becomes polylines
    reduced = true;
    std::array<double, 3> lo{}, hi{};
    lo.fill(std::numeric_limits<double>::max()), hi.fill(-std::numeric_limits<double>::max());
    auto grow = [&](const PathPoint& p) {
      for (std::size_t a = 0; a < 3; ++a) {
        double c = a == 0 ? p.x : a == 1 ? p.y : p.z;
        lo[a] = std::min(lo[a], c), hi[a] = std::max(hi[a], c);
      }
    };
    for (const auto& s : programmed) grow(s.start), grow(s.end);
    for (const auto& e : result.path) grow(e.start), grow(e.end);
    double span = 0;
    for (std::size_t a = 0; a < 3; ++a) span = std::max(span, hi[a] - lo[a]);
    sketch.limit = limits.points;
    sketch.tau = std::max(span, 1e-6) * 1e-5;  // a hundredth of a pixel on a picture 1000 px wide
    for (std::size_t k = 0; k < programmed.size(); ++k) add_programmed(programmed[k], planes[k]);
    for (const auto& e : result.path) add_path(e);
    programmed = {}, planes = {}, result.path = {};
  }
  void add_programmed(const ProgrammedSegment& s, Plane in_plane) {
    sketch.add(0, Style::kProgrammed, s.start, s.end, s.arc ? &s.center : nullptr, s.ccw, in_plane);
    label(s);
  }
  void add_path(const PathElement& e) {
    sketch.add(1, e.rapid ? Style::kRapid : Style::kFeed, e.start, e.end,
               e.type == ElementType::kArc ? &e.center : nullptr, e.ccw, plane);
  }
};

SvgPicture::SvgPicture(PictureLimits limits) : impl_(std::make_unique<Impl>()) { impl_->limits = limits; }
SvgPicture::~SvgPicture() = default;

void SvgPicture::programmed(const Block& b) {
  Impl& m = *impl_;
  std::optional<ProgrammedSegment> s = m.contour.add(b);
  if (!s) return;
  ++m.segments;
  if (m.reduced) return m.add_programmed(*s, b.state.plane);
  m.programmed.push_back(std::move(*s));
  m.planes.push_back(b.state.plane);
  if (m.programmed.size() > m.limits.full_elements) m.reduce();
}

void SvgPicture::element(const PathElement& e) {
  Impl& m = *impl_;
  ++m.elements;
  m.moved[0] = m.moved[0] || e.start.x != e.end.x;
  m.moved[1] = m.moved[1] || e.start.y != e.end.y;
  m.moved[2] = m.moved[2] || e.start.z != e.end.z;
  if (m.reduced) return m.add_path(e);
  m.result.path.push_back(e);
  if (m.result.path.size() > m.limits.full_elements) m.reduce();
}

void SvgPicture::alarm(const Alarm& a) { impl_->result.alarms.push_back(a); }

void SvgPicture::sar_variables(const SarVariables& v) {
  if (impl_->result.variables.size() < impl_->limits.markers)
    impl_->result.variables.push_back(v);
  else
    ++impl_->markers_dropped;
}

void SvgPicture::set_plane(Plane plane) { impl_->plane = plane; }

const std::vector<Alarm>& SvgPicture::alarms() const { return impl_->result.alarms; }

bool SvgPicture::reduced() const { return impl_->reduced; }
double SvgPicture::bound() const { return impl_->reduced ? impl_->sketch.bound() : 0.0; }

namespace {

// The reduced picture's extent: every point it keeps.
void fit_reduced(View& v, const Sketch& sketch, double width) {
  double lo_a = std::numeric_limits<double>::max(), lo_b = lo_a, hi_a = -lo_a, hi_b = -lo_a;
  for (const auto& s : sketch.strokes)
    for (const PathPoint& p : s.points)
      lo_a = std::min(lo_a, v.a(p)), hi_a = std::max(hi_a, v.a(p)), lo_b = std::min(lo_b, v.b(p)),
      hi_b = std::max(hi_b, v.b(p));
  if (lo_a > hi_a) lo_a = hi_a = lo_b = hi_b = 0;
  double span = std::max({hi_a - lo_a, hi_b - lo_b, 1e-9});
  v.scale = (width - 2 * v.pad) / span;
  v.min_a = lo_a, v.min_b = lo_b;
  v.height = (hi_b - lo_b) * v.scale + 2 * v.pad;
}

// Polylines in the styles of draw_panel, labels, SAR markers; in the side view only the path.
void draw_reduced(std::ostream& out, const View& v, const Sketch& sketch,
                  const std::vector<std::pair<PathPoint, std::string>>& labels,
                  const std::vector<SarVariables>& variables) {
  std::string d;
  for (const auto& s : sketch.strokes) {
    if (v.side && s.style == Style::kProgrammed) continue;
    d.clear();
    for (std::size_t k = 0; k < s.points.size(); ++k)
      d += fmt::format("{}{:.3f} {:.3f}", k == 0 ? "M " : " L ", v.sx(s.points[k]), v.sy(s.points[k]));
    const char* style = s.style == Style::kProgrammed ? "stroke=\"#999\" stroke-width=\"2\" stroke-dasharray=\"6 3\""
                        : s.style == Style::kRapid ? "stroke=\"#d62728\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\""
                                                   : "stroke=\"#1f5fbf\" stroke-width=\"2\"";
    out << fmt::format("<path d=\"{}\" fill=\"none\" {}/>\n", d, style);
  }
  // Labels where they do not cover one another: none within 40 px of one already drawn.
  std::vector<std::pair<double, double>> drawn;
  for (const auto& [p, text] : labels) {
    if (v.side) break;
    double x = v.sx(p), y = v.sy(p);
    bool clear = std::none_of(drawn.begin(), drawn.end(),
                              [&](const auto& q) { return std::hypot(q.first - x, q.second - y) < 40; });
    if (!clear) continue;
    drawn.emplace_back(x, y);
    out << fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#666\" font-size=\"10\">{}</text>\n", x + 3, y - 3,
                       text);
  }
  for (const auto& var : variables)
    for (const auto& [p, name] : {std::pair{var.p_apr, "P3"}, std::pair{var.p_aep, "P4"}})
      out << fmt::format(
          "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"3\" fill=\"#2ca02c\"/><text x=\"{:.1f}\" y=\"{:.1f}\" "
          "fill=\"#2ca02c\" font-size=\"11\">{} L{}</text>\n",
          v.sx(p), v.sy(p), v.sx(p) + 5, v.sy(p) + 14, name, var.line);
}

}  // namespace

void SvgPicture::write(std::ostream& out, const std::string& title) const {
  const Impl& m = *impl_;
  const std::vector<ProgrammedSegment>& programmed = m.programmed;
  const RunResult& result = m.result;
  const double width = 960, header = 60;
  View v;
  v.axes = plane_axes(m.plane);
  if (m.reduced)
    fit_reduced(v, m.sketch, width);
  else
    fit(v, programmed, result, width, true);
  v.top = header;
  // The side view, when anything moves along the applicate: abscissa against applicate, at the
  // plan view's scale.
  bool infeed = m.moved[static_cast<std::size_t>(v.axes.applicate)];
  View side;
  side.axes = {v.axes.abscissa, v.axes.applicate, v.axes.ordinate};
  side.side = true, side.plane = v.axes;
  if (infeed) {
    if (!m.reduced) fit(side, programmed, result, width, false);
    side.scale = v.scale, side.min_a = v.min_a;
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const auto& e : result.path)
      lo = std::min({lo, side.b(e.start), side.b(e.end)}), hi = std::max({hi, side.b(e.start), side.b(e.end)});
    for (const auto& s : m.sketch.strokes)
      if (s.style != Style::kProgrammed)
        for (const PathPoint& p : s.points) lo = std::min(lo, side.b(p)), hi = std::max(hi, side.b(p));
    side.min_b = lo;
    side.height = (hi - lo) * side.scale + 2 * side.pad;
    side.top = header + v.height + 20;
  }
  double total = header + v.height + (infeed ? side.height + 40 : 0) + 20 + (m.reduced ? 52 : 0);
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
  if (m.reduced) {
    // The reduction, stated at the foot of the picture.
    out << fmt::format(
        "<text x=\"{}\" y=\"{:.0f}\" fill=\"#b22222\">detail reduced for a long program: {} path elements and {} "
        "programmed segments</text>\n",
        v.pad, total - 46, m.elements, m.segments);
    out << fmt::format(
        "<text x=\"{}\" y=\"{:.0f}\" fill=\"#b22222\">drawn as polylines of {} points, each within {:.3g} mm of "
        "the exact path; transition circles drawn as feed;</text>\n",
        v.pad, total - 30, m.sketch.points, m.sketch.bound());
    out << fmt::format(
        "<text x=\"{}\" y=\"{:.0f}\" fill=\"#b22222\">no arrows or element titles; the label of one programmed segment "
        "in {} where labels do not cover one another{}.</text>\n",
        v.pad, total - 14, m.label_stride,
        m.markers_dropped
            ? fmt::format("; {} SAR markers beyond the first {} not drawn", m.markers_dropped, m.limits.markers)
            : std::string());
    draw_reduced(out, v, m.sketch, m.labels, result.variables);
  } else {
    draw_panel(out, v, programmed, result);
  }
  if (infeed) {
    out << fmt::format("<text x=\"{}\" y=\"{:.0f}\" font-weight=\"bold\">side view {}{} (infeed along {})</text>\n",
                       v.pad, side.top - 4, names[side.axes.abscissa], names[side.axes.ordinate],
                       names[side.axes.ordinate]);
    out << fmt::format("<line x1=\"0\" y1=\"{:.0f}\" x2=\"{:.0f}\" y2=\"{:.0f}\" stroke=\"#ddd\"/>\n", side.top - 20,
                       width, side.top - 20);
    if (m.reduced)
      draw_reduced(out, side, m.sketch, m.labels, result.variables);
    else
      draw_panel(out, side, programmed, result);
  }
  for (const auto& a : result.alarms)
    out << fmt::format("<text x=\"{}\" y=\"{:.0f}\" fill=\"#d62728\" font-weight=\"bold\">ALARM {} {}</text>\n", v.pad,
                       total - (m.reduced ? 62 : 10), a.number, a.text);
  out << "</svg>\n";
}

}  // namespace cutcom
