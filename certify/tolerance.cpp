// PROP-DIFF-1's tolerance model (docs/tolerances.md): the conditioning read off the program and
// ref's path, the coordinate and touching tolerances and each clause's decision band.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "compare.hpp"
#include "cutcom/sar_sequence.hpp"

namespace cutcom::props {

namespace {
// A corner between two directions: kappa, and chi where a circle makes it a crossing of
// carriers. A reversal or tangency within rounding (4 u) builds no intersection (a circle, or the
// common normal point): it does not count. Were the engines to intersect there after all, the
// tolerance is too tight and the campaign reports it -- the safe side.
// A corner between directions a and b (not normalised).
void count_corner(Conditioning& c, double aa, double ab, double ba, double bb, bool circle) {
  double norms = std::hypot(aa, ab) * std::hypot(ba, bb);
  double cosine = (aa * ba + ab * bb) / norms, sine = std::fabs(aa * bb - ab * ba) / norms;
  if (!std::isfinite(cosine) || !std::isfinite(sine)) return;
  // 1 + cos from the sine where the directions nearly reverse: 1 + cos in double is 0 there for
  // turns within 1e-8 of a half turn that are not exact (programmed decimals tell them apart, and
  // the equidistants then meet far out, PROP-HAIR-1).
  double one_plus_cos = cosine < 0 ? sine * sine / (1 - cosine) : 1 + cosine;
  if (one_plus_cos > 4 * kUnitRoundoff || (cosine < 0 && sine > 4 * kUnitRoundoff))
    c.corner = std::max(c.corner, 1 / one_plus_cos);
  if (circle && sine > 4 * kUnitRoundoff) c.crossing = std::max(c.crossing, 1 / sine);
}
// A block's programmed start tangent (ta, tb), end tangent (ua, ub) in the plane `ax` and its
// scale (the chord, or the radius where shorter).
struct ProgrammedTangents {
  double ta = 0, tb = 0, ua = 0, ub = 0, scale = 0;
};
ProgrammedTangents programmed_tangents(const Block& b, PlaneAxes ax) {
  auto at = [&](const Point3& p) {
    return std::pair{coord(p, ax.abscissa).to_double(), coord(p, ax.ordinate).to_double()};
  };
  auto [sa, sb] = at(b.start);
  auto [ea, eb] = at(b.end);
  ProgrammedTangents t;
  t.ta = ea - sa, t.tb = eb - sb, t.ua = t.ta, t.ub = t.tb;
  t.scale = std::hypot(t.ta, t.tb);
  if (b.is_arc()) {
    // The centre the engines use: the programmed one projected onto the chord's bisector
    // (ARC-CENTRE-1), or the CR= centre (ARC-CR-1). Tangents from the uncorrected centre can
    // miss a near-tangent corner by the end point's tolerance.
    double ma = (sa + ea) / 2, mb = (sb + eb) / 2, pa = -(eb - sb), pb = ea - sa;  // midpoint, perp(chord)
    double chord2 = pa * pa + pb * pb, ca = ma, cb = mb;
    if (b.centre) {
      auto [ka, kb] = at(*b.centre);
      ca = ka, cb = kb;
      if (chord2 > 0) {
        double k = ((ka - ma) * pa + (kb - mb) * pb) / chord2;
        ca = ma + k * pa, cb = mb + k * pb;
      }
    } else if (b.words.cr && chord2 > 0) {
      double cr = b.words.cr->to_double();
      double k = ((b.state.motion == Motion::kArcCcw) == (cr > 0) ? 1 : -1) *
                 std::sqrt(std::max(0.0, cr * cr / chord2 - 0.25));
      ca = ma + k * pa, cb = mb + k * pb;
    }
    double sense = b.state.motion == Motion::kArcCcw ? 1 : -1;
    t.ta = -sense * (sb - cb), t.tb = sense * (sa - ca);
    t.ua = -sense * (eb - cb), t.ub = sense * (ea - ca);
    double radius = std::hypot(sa - ca, sb - cb);
    t.scale = t.scale > 0 ? std::min(t.scale, radius) : radius;  // a full circle has no chord
  }
  return t;
}
}  // namespace

Conditioning conditioning_of(const std::vector<Block>& program, int window, const RunResult* generated) {
  Conditioning c;
  c.window = window;
  // End tangents of the last `window` traversing blocks: the look-ahead and CDON intersect a
  // block's equidistant with a later one's, however parallel (edge-cases.md: look-ahead crossing).
  std::vector<std::pair<double, double>> recent;
  double prev_a = 0, prev_b = 0;  // end tangent of the previous traversing block
  bool have_prev = false, prev_arc = false;
  Side side = Side::kOff;  // of the block before
  std::uint32_t selection = 0;
  for (const Block& b : program) {
    PlaneAxes ax = plane_axes(b.state.plane);
    for (const Point3* p : {&b.start, &b.end})
      c.size =
          std::max({c.size, std::fabs(p->x.to_double()), std::fabs(p->y.to_double()), std::fabs(p->z.to_double())});
    c.radius = std::max(c.radius, std::fabs(b.state.effective_radius().to_double()));
    if (b.moves_in_plane() || b.is_sar_block()) c.plane_lines.push_back(b.words.line);
    if ((b.moves_in_plane() && b.is_arc()) || b.is_sar_block()) c.circle_lines.push_back(b.words.line);
    // A new selection while compensation is on (TRC-SIDE-1, a side change; TRC-SIDE-2, the same
    // side again) approaches from where the tool is.
    bool reselected =
        b.state.side != Side::kOff && side != Side::kOff && (b.state.side != side || b.state.selection != selection);
    if (b.is_sar_block() || reselected) c.computed_lines.push_back(b.words.line);
    side = b.state.side, selection = b.state.selection;
    if (b.is_sar_block() && b.words.disr) {
      // SAR-DISR-1/2: the generated element is L = DISR + r long, or of radius DISR +- r.
      double d = b.words.disr->to_double(), r = std::fabs(b.state.effective_radius().to_double());
      for (double l : {std::fabs(d), std::fabs(d + r), std::fabs(d - r)})
        if (l > 0) c.shortest = std::min(c.shortest, l);
      // P3 lies L or R from P4 along the tangent of the block next to it: a rounded tangent
      // tilts it by up to u (L / d_min) per unit of that length, as the radius does an offset.
      c.radius = std::max(c.radius, std::fabs(d) + r);
      continue;
    }
    if (!b.moves_in_plane()) continue;
    auto [ta, tb, ua, ub, scale] = programmed_tangents(b, ax);
    if (scale > 0) c.shortest = std::min(c.shortest, scale);
    for (std::size_t j = 0; j + 1 < recent.size(); ++j) {  // non-adjacent pairs; the adjacent one below
      double pa = recent[j].first, pb = recent[j].second;
      double sine = std::fabs(pa * tb - pb * ta) / (std::hypot(pa, pb) * std::hypot(ta, tb));
      // Exactly parallel blocks have no intersection to compute (programmed directions are
      // multiples of each other): they do not count.
      if (std::isfinite(sine) && sine > 4 * kUnitRoundoff) c.crossing = std::max(c.crossing, 1 / sine);
    }
    if (have_prev) count_corner(c, prev_a, prev_b, ta, tb, b.is_arc() || prev_arc);
    prev_a = ua, prev_b = ub, have_prev = true, prev_arc = b.is_arc();
    recent.emplace_back(ua, ub);
    if (static_cast<int>(recent.size()) > window + 1) recent.erase(recent.begin());
  }
  c.size = std::max(c.size, c.radius);
  if (generated) add_generated(c, program, *generated);
  return c;
}

namespace {
double along(const PathPoint& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

// In-plane tangent of a path element at its start (or end): the chord of a line, the
// perpendicular of the radius of an arc (ccw about the applicate is ccw in (abscissa, ordinate)).
std::pair<double, double> tangent(const PathElement& e, const PlaneAxes& ax, bool at_end) {
  auto ab = [&](const PathPoint& p) { return std::pair{along(p, ax.abscissa), along(p, ax.ordinate)}; };
  auto [sa, sb] = ab(e.start);
  auto [ea, eb] = ab(e.end);
  if (e.type == ElementType::kLine) return {ea - sa, eb - sb};
  auto [ca, cb] = ab(e.center);
  double pa = (at_end ? ea : sa) - ca, pb = (at_end ? eb : sb) - cb, sense = e.ccw ? 1 : -1;
  return {-sense * pb, sense * pa};
}
}  // namespace

namespace {
// The SAR block's elements (ref's path) meet the programmed contour next to them at corners the
// program does not show: tangent by construction (SAR-POINTS-1/2), but an equidistant extended
// past its block may meet them at any angle (campaign 20261320, case 366861: a side change's
// first block, too short, extended by G462 to a retraction's lead at 178.5 degrees).
void count_contour_joints(Conditioning& c, const std::vector<Block>& program, const Block& sar, const RunResult& ref,
                          PlaneAxes ax) {
  // Every element of the block that moves in the plane, the lead included: the contour may meet
  // the lead (case 366861 does), so add_generated's SAR element alone would miss it.
  const PathElement *first = nullptr, *last = nullptr;
  for (const PathElement& e : ref.path) {
    auto [ta, tb] = tangent(e, ax, false);
    if (e.origin.line != sar.words.line || std::hypot(ta, tb) == 0) continue;
    first = first ? first : &e, last = &e;
  }
  if (!first) return;
  // An approach meets the contour after it, a retraction the contour before it (a block further
  // away, past moves without compensation, makes no corner with it).
  bool approach = SarSequence::is_approach(sar);
  const Block *before = nullptr, *after = nullptr;
  for (const Block& b : program) {
    if (!b.moves_in_plane() || b.is_sar_block() || b.state.plane != sar.state.plane) continue;
    if (b.words.line < sar.words.line && !approach) before = &b;
    if (b.words.line > sar.words.line && approach && !after) after = &b;
  }
  if (before) {
    ProgrammedTangents t = programmed_tangents(*before, ax);
    auto [ta, tb] = tangent(*first, ax, false);
    count_corner(c, t.ua, t.ub, ta, tb, before->is_arc() || first->type == ElementType::kArc);
  }
  if (after) {
    ProgrammedTangents t = programmed_tangents(*after, ax);
    auto [ua, ub] = tangent(*last, ax, true);
    count_corner(c, ua, ub, t.ta, t.tb, after->is_arc() || last->type == ElementType::kArc);
  }
}
}  // namespace

void add_generated(Conditioning& c, const std::vector<Block>& program, const RunResult& ref) {
  for (const PathElement& e : ref.path)
    for (const PathPoint* p : {&e.start, &e.end, &e.center})
      c.reach = std::max({c.reach, std::fabs(p->x), std::fabs(p->y), std::fabs(p->z)});
  for (const Block& b : program) {
    if (!b.is_sar_block()) continue;
    PlaneAxes ax = plane_axes(b.state.plane);
    // SAR-SUB-1: the lead (P0 -> P1, in the plane) meets the SAR element at a corner the program
    // does not show; with KONT G451 behind the contour it is an intersection (TRC-KONT-4).
    const PathElement *lead = nullptr, *first = nullptr, *last = nullptr;
    bool lead_after = false;
    for (const PathElement& e : ref.path) {
      if (e.origin.line != b.words.line) continue;
      auto [ta, tb] = tangent(e, ax, false);
      if (e.origin.sar == SarMove::kLead && std::hypot(ta, tb) > 0 && !lead) lead = &e, lead_after = first != nullptr;
      if (e.origin.sar == SarMove::kElement) first = first ? first : &e, last = &e;
    }
    count_contour_joints(c, program, b, ref, ax);
    if (!lead || !first) continue;
    auto [da, db] = tangent(*lead, ax, false);
    auto [ta, tb] = lead_after ? tangent(*last, ax, true) : tangent(*first, ax, false);
    count_corner(c, da, db, ta, tb, (lead_after ? last : first)->type == ElementType::kArc);
  }
  // TRC-KONT-4 (and the same at a side change): the approach line meets the first equidistant,
  // the last one the retraction line, at an intersection the program does not show; nearly
  // reversed, it lies far out (campaign 20261204, case 45849: 179.82 degrees, 2,400 mm away).
  // The approach line may be the path's last element: an alarm after it stops the run before the
  // equidistant it met (campaign 20261283, case 775245: a SAR lead 144,560 mm out, then alarm
  // 10742); the programmed line after it tells the corner then.
  for (std::size_t k = 0; k < ref.path.size(); ++k) {
    const PathElement& a = ref.path[k];
    const PathElement* following = k + 1 < ref.path.size() ? &ref.path[k + 1] : nullptr;
    bool approach = a.origin.kind == OriginKind::kApproach && a.type == ElementType::kLine &&
                    (!following || following->origin.kind != OriginKind::kApproach);
    bool retraction = following && following->origin.kind == OriginKind::kRetraction &&
                      following->type == ElementType::kLine && a.origin.kind != OriginKind::kRetraction;
    if (!approach && !retraction) continue;
    // (A SAR lead meets its element here too where P4 lies in a later block: campaign 20261211,
    // case 83509, 179.994 degrees, 34,860 mm out.)
    int line = (approach ? a : *following).origin.line;
    if (std::none_of(ref.decisions.begin(), ref.decisions.end(), [&](const Decision& d) {
          return d.clause == "TRC-KONT-4" && d.branch == "intersection" && d.line == line;
        }))
      continue;
    PlaneAxes ax = plane_axes(Plane::kG17);
    for (const Block& blk : program)
      if (blk.words.line == line) ax = plane_axes(blk.state.plane);
    auto moves = [&](const PathElement& e) {
      auto [ea, eb] = tangent(e, ax, false);
      return std::hypot(ea, eb) > 0;
    };
    // Infeeds between them do not turn the corner (campaign 20261226, case 804096: a side change
    // whose approach line meets, past three infeeds in Z, an equidistant 7,000 mm out that the
    // run never reached: it stopped with an alarm first). Then the programmed line tells.
    const PathElement* before = &a;
    const PathElement* after = following;
    std::optional<std::pair<double, double>> programmed;
    if (approach) {
      std::size_t j = k + 1;
      while (j < ref.path.size() && !moves(ref.path[j])) ++j;
      after = j < ref.path.size() ? &ref.path[j] : nullptr;
      auto next = after ? program.end() : std::find_if(program.begin(), program.end(), [&](const Block& blk) {
        return blk.words.line > line && blk.moves_in_plane();
      });
      // (An arc's from its centre, as the engines correct it: campaign 20261283, case 775245 shrunk,
      // a SAR lead meeting the equidistant of a circle that then collapsed.)
      if (next != program.end()) {
        ProgrammedTangents t = programmed_tangents(*next, ax);
        programmed = std::pair{t.ta, t.tb};
      }
    } else {
      std::size_t j = k + 1;
      while (j > 0 && !moves(ref.path[j - 1])) --j;
      before = j > 0 ? &ref.path[j - 1] : nullptr;
    }
    if (!before || (!after && !programmed)) continue;
    auto [da, db] = tangent(*before, ax, true);
    auto [ta, tb] = after ? tangent(*after, ax, false) : *programmed;
    if (std::hypot(da, db) > 0 && std::hypot(ta, tb) > 0)
      count_corner(c, da, db, ta, tb, before->type == ElementType::kArc || (after && after->type == ElementType::kArc));
  }
  // Carriers that nearly touch (a gap g, mm) cross at about sqrt(2 |g| / R), R <= L: the corner's
  // deflection may be large while the intersection is as ill-conditioned as a tangency. A gap
  // within the tolerance is a touching decision (compare: the touching tolerance) instead.
  const double touching = Tolerance::for_program(c).coordinate;
  for (const Decision& d : ref.decisions) {
    // (TRC-CD-3, TRC-LOOK-2, TRC-EDGE-5: the least slack counts the carriers' overlap as well.)
    bool gap = d.clause == "TRC-ARC-CORNER-1" ||
               (d.clause == "TRC-CD-2" && (d.branch == "g451-meets" || d.branch == "g451-misses")) ||
               (d.clause == "TRC-CD-3" && d.branch == "cut") ||
               (d.clause == "TRC-LOOK-2" && d.branch == "intersection") ||
               (d.clause == "TRC-EDGE-5" && d.branch == "hit");
    double g = std::fabs(margin_value(d));
    if (gap && d.has_margin && g > touching) c.crossing = std::max(c.crossing, std::sqrt(c.size / (2 * g)));
  }
}

Tolerance Tolerance::for_program(const Conditioning& c) {
  Tolerance t;
  double leverage = c.size / c.shortest;  // how far a rounded input tilts the shortest direction
  t.coordinate =
      64 * kUnitRoundoff * (std::max(c.size, c.reach) + c.radius * leverage * c.corner + c.size * c.crossing);
  t.sine = 16 * kUnitRoundoff * leverage;
  t.degrees = t.sine * 180 / 3.14159265358979323846;
  t.touching = std::sqrt(4 * c.size * t.coordinate) + t.coordinate;
  t.window = std::max(c.window, 0) + 1;
  t.plane_lines = c.plane_lines;
  std::sort(t.plane_lines.begin(), t.plane_lines.end());
  t.circle_lines = c.circle_lines;
  std::sort(t.circle_lines.begin(), t.circle_lines.end());
  t.computed_lines = c.computed_lines;
  std::sort(t.computed_lines.begin(), t.computed_lines.end());
  return t;
}

double Tolerance::band(std::string_view clause) const {
  if (clause == "TRC-CORNER-1") return sine;
  if (clause == "TRC-CD-2") return std::max(sine, coordinate);  // the entry's corner kind, or where it starts
  if (clause == "TRC-CORNER-3" || clause == "TRC-CORNER-4") return degrees;
  if (clause == "TRC-ELEMENT-1" || clause == "TRC-ARC-ELEMENT-1" || clause == "TRC-APPR-NORM-1" ||
      clause == "TRC-RETR-NORM-1" || clause == "TRC-KONT-1" || clause == "TRC-KONT-2" || clause == "TRC-EDGE-5" ||
      clause == "TRC-EDGE-6" || clause == "TRC-CD-5" || clause == "TRC-CD-6" || clause == "TRC-LOOK-1" ||
      clause == "TRC-LOOK-2" || clause == "TRC-LOOK-4" || clause == "TRC-ARC-EQ-1" || clause == "ARC-CENTRE-2" ||
      clause == "ARC-CR-1" || clause == "TRC-ARC-CORNER-1" || clause == "TRC-CD-3" || clause == "SAR-SIDE-2" ||
      clause == "SAR-DISR-1" || clause == "SAR-DISR-2" || clause == "SAR-DISCL-3" || clause == "SAR-SUB-1")
    return coordinate;
  return 0;  // decisions on exact decimals (block kinds, alarms) never diverge
}

}  // namespace cutcom::props
