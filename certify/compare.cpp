#include "compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>

#include "cutcom/boundary_rules.hpp"

namespace cutcom::props {

namespace {
double distance(const PathPoint& a, const PathPoint& b) {
  return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

// How far an arc turns, in [0, 2π], in its plane: the axis on which centre and start agree is the
// applicate (both engines put the centre at the start's applicate; a helix's end leaves it); of
// several, the one in whose plane start and end are equally far from the centre, and of two
// equally so within rounding, the one on which the end agrees too. A full circle
// (start == end) turns 2π; otherwise the angle between the radius vectors u, v, or 2π minus it,
// by the sense of u × v against the arc's direction (counter-clockwise seen from the positive
// applicate axis). Empty where that sense is within the rounding of u × v (start and end a few
// ulps apart) or no axis qualifies: the sweep cannot be told from the points.
constexpr int kPlane[3][2] = {{1, 2}, {2, 0}, {0, 1}};  // (abscissa, ordinate) about axis k

// Whether the arc's start lies level with its centre on axis k: k may be the arc's axis.
bool level_on(const PathElement& e, int k) {
  return k == 0 ? e.center.x == e.start.x : k == 1 ? e.center.y == e.start.y : e.center.z == e.start.z;
}

// The axis sweep_of measures an arc about (-1: none qualifies).
int sweep_axis(const PathElement& e) {
  const double c[3] = {e.center.x, e.center.y, e.center.z}, s[3] = {e.start.x, e.start.y, e.start.z},
               t[3] = {e.end.x, e.end.y, e.end.z};
  int best = -1;
  double best_mismatch = 0;
  bool best_flat = false;
  for (int k = 0; k < 3; ++k) {
    if (!level_on(e, k)) continue;
    int a = kPlane[k][0], b = kPlane[k][1];
    // An axis on which the end agrees too is the applicate of a circle in its plane: it wins over
    // one where only the start happens to lie level with the centre (a start on the centre's x).
    bool flat = t[k] == c[k];
    double rs = std::hypot(s[a] - c[a], s[b] - c[b]), rt = std::hypot(t[a] - c[a], t[b] - c[b]);
    double mismatch = std::fabs(rs - rt);
    // Mismatches within rounding of the radius are a tie, which the flat axis wins.
    bool tie = best >= 0 && std::fabs(mismatch - best_mismatch) <= 16 * kUnitRoundoff * std::max(rs, rt);
    if (best < 0 || (tie ? flat && !best_flat : mismatch < best_mismatch))
      best = k, best_mismatch = mismatch, best_flat = flat;
  }
  return best;
}

std::optional<double> sweep_of(const PathElement& e, int axis = -1) {  // about `axis` where it qualifies
  if (e.start.x == e.end.x && e.start.y == e.end.y && e.start.z == e.end.z) return 2 * std::numbers::pi;
  const double c[3] = {e.center.x, e.center.y, e.center.z}, s[3] = {e.start.x, e.start.y, e.start.z},
               t[3] = {e.end.x, e.end.y, e.end.z};
  int best = axis >= 0 && level_on(e, axis) ? axis : sweep_axis(e);
  if (best < 0) return std::nullopt;
  int a = kPlane[best][0], b = kPlane[best][1];
  double ua = s[a] - c[a], ub = s[b] - c[b], va = t[a] - c[a], vb = t[b] - c[b];
  double cross = ua * vb - ub * va, dot = ua * va + ub * vb;
  double nu = std::hypot(ua, ub), nv = std::hypot(va, vb);
  if (!(std::fabs(cross) > 64 * kUnitRoundoff * (nu + nv) * std::max(nu, nv)) && dot > 0)
    return std::nullopt;  // nearly parallel: a sliver or nearly a full circle, too close to tell
  double angle = std::atan2(std::fabs(cross), dot);  // in [0, π]
  return (cross > 0) == e.ccw ? angle : 2 * std::numbers::pi - angle;
}
// The radius at the start, for lengths along the circle (a helix's is its radius in the plane).
double radius_of(const PathElement& e) {
  return std::max({std::hypot(e.start.x - e.center.x, e.start.y - e.center.y),
                   std::hypot(e.start.y - e.center.y, e.start.z - e.center.z),
                   std::hypot(e.start.z - e.center.z, e.start.x - e.center.x)});
}
}  // namespace

namespace {
// A decision at carriers that just touch: its point is the intersection of nearly tangent
// carriers (a line tangent to the G461 circle, circles touching at a corner), ill-conditioned
// by a square root. Inside the band both branches are legitimate and the point is known only
// to within Tolerance::touching.
// A CDON entry (TRC-CD-2 `entry`) is such a decision only at a corner with a circle, where its
// margin is also how near the carriers come to missing each other; between two lines it is the
// entry's extent, and its point, where two lines meet, is well conditioned: an entry of one
// point (extent 0) is still compared (mutant 23 hid behind this).
bool entry_at_circle(const Decision& d, const Tolerance& tol) {
  if (tol.plane_lines.empty()) return true;  // blocks unknown: as before, any entry
  auto circle = [&](int line) { return std::binary_search(tol.circle_lines.begin(), tol.circle_lines.end(), line); };
  auto at = std::lower_bound(tol.plane_lines.begin(), tol.plane_lines.end(), d.line);
  return circle(d.line) || (at != tol.plane_lines.begin() && circle(*std::prev(at)));
}
// The decision's own margin lies inside its clause's band: at the knife edge by the margin alone.
bool margin_in_band(const Decision& d, const Tolerance& tol) {
  return d.has_margin && std::fabs(margin_value(d)) <= tol.band(d.clause);
}
bool touching_carriers(const Decision& d, const Tolerance& tol) {
  bool kind = (d.clause == "TRC-CD-2" && (d.branch == "g451-meets" || d.branch == "g451-misses")) ||
              d.clause == "TRC-ARC-CORNER-1" || (d.clause == "TRC-EDGE-5" && d.branch == "hit") ||
              (d.clause == "TRC-EDGE-6" && d.branch == "circle") || d.clause == "TRC-LOOK-2" ||
              d.clause == "TRC-CD-5" || d.clause == "TRC-CD-6" ||
              (d.clause == "TRC-CD-2" && d.branch == "entry" && entry_at_circle(d, tol));
  return kind && margin_in_band(d, tol);
}
}  // namespace

namespace {
// A crossing that touches a piece's end or is tangent to it, ref's margin inside the band: a
// bottleneck's cut (TRC-CD-3 `cut`) or the retraction's hit further back (TRC-CD-5
// `earlier-block`, whose boundary rule is TRC-CD-3's; campaign 20261234, case 48846: a G461
// circle tangent to an equidistant at its start, hit 1.8e-8 mm into it by fast, at the joint by
// ref).
bool touching_crossing(const Decision& d, const Tolerance& tol) {
  bool kind = (d.clause == "TRC-CD-3" && d.branch == "cut") || (d.clause == "TRC-CD-5" && d.branch == "earlier-block");
  return kind && margin_in_band(d, tol);
}

// An overlap of collinear pieces (TRC-CD-3 `overlap`) is a near miss of exactly 0: the same
// touching as a crossing at 0, found where an entry lies along a held piece instead of across it.
bool touching_overlap(const Decision& d, const Tolerance& tol) {
  return d.clause == "TRC-CD-3" && d.branch == "overlap" && margin_in_band(d, tol);
}

// fast's hit where its carriers touch (its margin in the band: their overlap about 0) and ref's
// point lies just off the piece: at carriers that touch, the point along them is known only to
// within Tolerance::touching, so ref's miss by less than that is the same knife edge (campaign
// 20261286, case 993226: a G461 circle exactly tangent to a later block's equidistant 1e-9 mm
// before its normal start; ref `none` at -1e-9, fast `later-block` at 2e-15).
bool touching_hit(const Decision& r, const Decision& f, const Tolerance& tol) {
  bool kind = (f.clause == "TRC-EDGE-5" && f.branch == "hit") || (f.clause == "TRC-CD-6" && f.branch == "later-block");
  return kind && margin_in_band(f, tol) && r.has_margin && std::fabs(margin_value(r)) <= tol.touching;
}

// What fast's decision touches where ref's at the same place does not (the verdict's words), or
// empty: the three knife edges above, ref and fast at the same clause and line.
std::string_view fast_touching(const Decision& r, const Decision& f, const Tolerance& tol) {
  if (r.clause != f.clause || r.line != f.line) return {};
  if (touching_overlap(f, tol)) return "fast's entry overlaps";
  if (touching_crossing(f, tol)) return "fast's crossing touches";
  if (touching_hit(r, f, tol)) return "fast's hit on touching carriers";
  return {};
}

// A crossing that touches a piece's end (touching_crossing) may be taken on either
// piece at the joint: the engines then skip different blocks and hold different pieces after it.
// Likewise after carriers that just touch (an intersection of nearly tangent circles: the point
// moves by up to sqrt(band L) along them, and what is built on it with it). True (a knife edge
// in `v`) when one of ref's first `upto` decisions is such a one.
bool parted_after_touching(const RunResult& ref, std::size_t from, std::size_t upto, const Tolerance& tol,
                           const std::string& where, Verdict& v) {
  for (std::size_t k = from; k < upto; ++k) {
    const Decision& p = ref.decisions[k];
    bool crossing = touching_crossing(p, tol);
    if (crossing || touching_carriers(p, tol)) {
      v.kind = Verdict::Kind::kKnifeEdge;
      v.clause = std::string(p.clause);
      v.explanation = where + (crossing ? ", after a touching crossing" : ", after touching carriers");
      return true;
    }
  }
  return false;
}
}  // namespace

namespace {
// PROP-DIFF-1: an equidistant radius of exactly 0 (R = r in programmed decimals) is decided in
// integers by both engines (TRC-ARC-EQ-1 and the collapsed circles of TRC-CD-2): no knife edge.
bool decided_exactly_at_zero(const Decision& d) {
  return d.margin_exact == "0" &&
         (d.clause == "TRC-ARC-EQ-1" ||
          (d.clause == "TRC-CD-2" && (d.branch == "collapsed" || d.branch == "after-collapse")));
}

// PROP-DIFF-1: fast decides TRC-CORNER-1 and TRC-KONT-1 exactly wherever the tangents and the
// start are programmed decimals (lines, I/J/K and CR= circles): an exact tie there is no knife
// edge. Only at or next to a block about which fast computes points (a SAR block, a new selection
// under compensation: Conditioning::computed_lines) may it take the other branch at ref's margin
// of exactly 0. Blocks unknown: as before.
bool decided_on_decimals(const Decision& d, const Tolerance& tol) {
  if (d.margin_exact != "0" || (d.clause != "TRC-CORNER-1" && d.clause != "TRC-KONT-1") || tol.plane_lines.empty())
    return false;
  const std::vector<int>& p = tol.plane_lines;
  auto computed = [&](int line) {
    return std::binary_search(tol.computed_lines.begin(), tol.computed_lines.end(), line);
  };
  auto at = static_cast<std::size_t>(std::lower_bound(p.begin(), p.end(), d.line) - p.begin());
  if (computed(d.line) || (at > 0 && computed(p[at - 1]))) return false;
  for (std::size_t k = at; k < p.size() && k <= at + 1; ++k)
    if (computed(p[k])) return false;
  return true;
}

// The sign of a decision's margin: fast's double, or ref's text whose sign is exact ("0" only
// for an exact tie). Empty for a NaN, which no rule admits.
std::optional<int> margin_sign(const Decision& d) {
  if (d.margin_exact.empty()) {
    if (std::isnan(d.margin)) return std::nullopt;
    return (d.margin > 0) - (d.margin < 0);
  }
  // ref writes "0" for an exact tie and nothing else: a tiny margin whose digits underflow to
  // "0.00000000000000000e+00" keeps the sign of its text.
  const std::string& t = d.margin_exact;
  if (t == "0") return 0;
  return t[0] == '-' ? -1 : 1;
}
}  // namespace

// PROP-BOUNDARY-1: each engine's branch agrees with its own margin under the clause's boundary
// rule. A branch taken against its own margin is a wrong comparison at the threshold (`<` for
// `<=`), whatever the other engine did: never a knife edge.
std::optional<std::string> broken_boundary_rule(const RunResult& run, std::string_view engine) {
  for (std::size_t i = 0; i < run.decisions.size(); ++i) {
    const Decision& d = run.decisions[i];
    if (!d.has_margin) continue;
    const BoundaryRule* rule = boundary_rule(d.clause, d.branch);
    if (!rule) continue;
    std::optional<int> sign = margin_sign(d);
    if (sign && satisfies(rule->margin, *sign)) continue;
    return fmt::format("{} decision {}: {} line {} `{}` with margin {} breaks its boundary rule (`{}` needs margin {})",
                       engine, i, d.clause, d.line, d.branch,
                       d.margin_exact.empty() ? fmt::format("{}", d.margin) : d.margin_exact, d.branch,
                       requirement_text(rule->margin));
  }
  return std::nullopt;
}

// PATH-ELEMENT-1 in fast's own numbers: fast writes no element whose start and end are the same
// double and that does not turn (a line, an arc of radius 0). It decides "zero length" on the very
// numbers it writes, so such an element is a decision against its own result. (ref decides on
// exact values and rounds after: an exact sliver may print as one point, which is no breach.)
std::optional<std::string> zero_length_element(const RunResult& run, std::string_view engine) {
  for (std::size_t i = 0; i < run.path.size(); ++i) {
    const PathElement& e = run.path[i];
    bool closed = e.start.x == e.end.x && e.start.y == e.end.y && e.start.z == e.end.z;
    bool point =
        e.type != ElementType::kArc || (e.center.x == e.start.x && e.center.y == e.start.y && e.center.z == e.start.z);
    if (closed && point)
      return fmt::format("{} element {} ({}) has length zero (PATH-ELEMENT-1: not output)", engine, i,
                         describe(e.origin));
  }
  return std::nullopt;
}

// PATH-ELEMENT-2 in fast's own numbers: an arc reads as it turns from its written points alone, so
// fast writes none whose end lies in its start's direction from the centre within rounding and is
// not its start (sweep_of cannot tell a sliver from a whole turn there). fast decides readability
// on the numbers it writes; ref rounds exact points once and is judged against fast instead.
std::optional<std::string> undetermined_turn(const RunResult& run, std::string_view engine) {
  for (std::size_t i = 0; i < run.path.size(); ++i) {
    const PathElement& e = run.path[i];
    int axis = e.type == ElementType::kArc ? sweep_axis(e) : -1;
    if (axis < 0 || sweep_of(e, axis)) continue;
    // A helix whose end lies over its start turns a whole turn (its points differ in height only).
    const double s[3] = {e.start.x, e.start.y, e.start.z}, t[3] = {e.end.x, e.end.y, e.end.z};
    if (s[kPlane[axis][0]] == t[kPlane[axis][0]] && s[kPlane[axis][1]] == t[kPlane[axis][1]]) continue;
    return fmt::format("{} element {} ({}) is an arc whose end points leave its turn undetermined (PATH-ELEMENT-2)",
                       engine, i, describe(e.origin));
  }
  return std::nullopt;
}

std::optional<std::string> untraced_difference(const RunResult& traced, const RunResult& untraced,
                                               std::string_view engine) {
  auto same = [](const PathPoint& a, const PathPoint& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
  if (traced.path.size() != untraced.path.size())
    return fmt::format("{} without its trace: {} elements, with it {}", engine, untraced.path.size(),
                       traced.path.size());
  for (std::size_t i = 0; i < traced.path.size(); ++i) {
    const PathElement &a = traced.path[i], &b = untraced.path[i];
    bool arc = a.type == ElementType::kArc;
    if (a.type != b.type || a.rapid != b.rapid || !same(a.start, b.start) || !same(a.end, b.end) ||
        (arc && (!same(a.center, b.center) || a.ccw != b.ccw)) || a.origin != b.origin || a.feed != b.feed ||
        a.feed_type != b.feed_type)
      return fmt::format("{} without its trace: element {} ({}) differs", engine, i, describe(a.origin));
  }
  if (traced.actions.size() != untraced.actions.size())
    return fmt::format("{} without its trace: {} actions, with it {}", engine, untraced.actions.size(),
                       traced.actions.size());
  for (std::size_t i = 0; i < traced.actions.size(); ++i)
    if (traced.actions[i].line != untraced.actions[i].line || !same(traced.actions[i].at, untraced.actions[i].at))
      return fmt::format("{} without its trace: action {} at line {} differs", engine, i, traced.actions[i].line);
  if (traced.alarms.size() != untraced.alarms.size())
    return fmt::format("{} without its trace: {} alarms, with it {}", engine, untraced.alarms.size(),
                       traced.alarms.size());
  for (std::size_t i = 0; i < traced.alarms.size(); ++i)
    if (traced.alarms[i].number != untraced.alarms[i].number || traced.alarms[i].line != untraced.alarms[i].line)
      return fmt::format("{} without its trace: alarm {} line {}, with it {} line {}", engine,
                         untraced.alarms[i].number, untraced.alarms[i].line, traced.alarms[i].number,
                         traced.alarms[i].line);
  return std::nullopt;
}

namespace {
// The path's elements follow the program's lines (a program without loops or subprograms called
// twice): only then does "a later block" mean the same block in both runs (PROP-DIFF-2).
bool lines_ascend(const std::vector<PathElement>& path) {
  for (std::size_t k = 1; k < path.size(); ++k)
    if (path[k].origin.line < path[k - 1].origin.line) return false;
  return true;
}
bool same_decision(const Decision& r, const Decision& f) {
  return r.clause == f.clause && r.line == f.line && r.branch == f.branch;
}
// The line whose block began a look-ahead still searching after the first `end` decisions
// (TRC-LOOK-1 `too-short` with no intersection found, no blocks skipped and no deselection's
// strategy taken since: TRC-LOOK-2/3, TRC-EDGE-1).
std::optional<int> searching_at(const std::vector<Decision>& d, std::size_t end) {
  std::optional<int> began;
  for (std::size_t k = 0; k < end && k < d.size(); ++k) {
    if (d[k].clause == "TRC-LOOK-1" && d[k].branch == "too-short" && !began) began = d[k].line;
    if ((d[k].clause == "TRC-LOOK-2" && d[k].branch == "intersection") || d[k].clause == "TRC-LOOK-3" ||
        d[k].clause == "TRC-EDGE-1")
      began.reset();
  }
  return began;
}
}  // namespace

Verdict compare(const RunResult& ref, const RunResult& fast, const Tolerance& tol) {
  Verdict v;
  // PROP-DIFF-2: after a knife edge the runs are compared again from the first later block where
  // they take the same branch; `resumed` is the block after which they did (-1: never parted).
  Verdict knife;
  int resumed = -1;
  auto diverge = [&](std::string why) {
    v.kind = Verdict::Kind::kDiverge;
    v.explanation = resumed < 0 ? std::move(why)
                                : fmt::format(
                                      "after a knife edge ({}) the runs took the same branches again at "
                                      "line {}, then: {}",
                                      knife.explanation, resumed, why);
    return v;
  };
  for (auto [run, engine] : {std::pair{&fast, "fast"}, std::pair{&ref, "ref"}})
    if (std::optional<std::string> broken = broken_boundary_rule(*run, engine)) return diverge(*broken);
  if (std::optional<std::string> zero = zero_length_element(fast, "fast")) return diverge(*zero);
  if (std::optional<std::string> unread = undetermined_turn(fast, "fast")) return diverge(*unread);
  // PROP-DIFF-2: after a knife edge at line L, decisions about lines up to L and the next
  // `window` blocks are the knife edge's (also those a look-ahead takes later); the first ones
  // after them must be the same decision.
  const bool can_resume = lines_ascend(ref.path) && lines_ascend(fast.path);
  int parted_upto = std::numeric_limits<int>::min();
  auto skip = [&](const std::vector<Decision>& d, std::size_t& k) {
    while (k < d.size() && d[k].line <= parted_upto) ++k;
  };
  // ref's margin lies inside the clause's band: either branch is legitimate (PROP-DIFF-1).
  auto in_band = [&](const Decision& d) {
    return margin_in_band(d, tol) && !decided_exactly_at_zero(d) && !decided_on_decimals(d, tol);
  };
  std::size_t ir = 0, jf = 0, resumed_at = 0;
  for (;; ++ir, ++jf) {
    skip(ref.decisions, ir), skip(fast.decisions, jf);
    if (ir == ref.decisions.size() || jf == fast.decisions.size()) break;
    const Decision& r = ref.decisions[ir];
    const Decision& f = fast.decisions[jf];
    if (same_decision(r, f)) continue;
    std::string where = fmt::format("{}: ref {} line {} {} (margin {}), fast {} line {} {} (margin {})",
                                    ir == jf ? fmt::format("decision {}", ir) : fmt::format("decisions {}/{}", ir, jf),
                                    r.clause, r.line, r.branch, r.margin_exact, f.clause, f.line, f.branch, f.margin);
    // A decision without a margin never parts the runs legitimately. Where ref's margin lies in the
    // band the other branch may also show as another clause next (an element that exists in fast
    // and collapses in ref is searched first: TRC-CD-6 before TRC-ARC-EQ-1).
    if (in_band(r)) {
      if (resumed < 0) {  // legitimate: ref's margin lies inside the band
        knife.kind = Verdict::Kind::kKnifeEdge;
        knife.clause = std::string(r.clause);
        knife.explanation = where + fmt::format(", band {:.3g}", tol.band(r.clause));
      }
      if (!can_resume) return knife;
      // Decisions about the next `window` blocks may follow from the knife edge (a corner, a
      // look-ahead, a bottleneck check reach that far): they are the knife edge's too.
      auto moves = [&](int line) {
        return tol.plane_lines.empty() || std::binary_search(tol.plane_lines.begin(), tol.plane_lines.end(), line);
      };
      // The last line of the blocks a knife edge at `line` (ref's decision `from` on) owns; empty
      // where the program ends before them.
      auto reach = [&](std::size_t from, int line) -> std::optional<int> {
        std::vector<int> later;
        for (std::size_t k = from; k < ref.decisions.size(); ++k)
          if (ref.decisions[k].line > line && moves(ref.decisions[k].line)) later.push_back(ref.decisions[k].line);
        std::sort(later.begin(), later.end());
        later.erase(std::unique(later.begin(), later.end()), later.end());
        if (later.size() <= static_cast<std::size_t>(tol.window)) return std::nullopt;
        return later[static_cast<std::size_t>(tol.window) - 1];
      };
      std::optional<int> upto = reach(ir, std::max(r.line, f.line));
      if (!upto) return knife;
      parted_upto = std::max(parted_upto, *upto);
      const std::size_t ir_parted = ir, jf_parted = jf;
      skip(ref.decisions, ir), skip(fast.decisions, jf);
      // The knife edge's blocks grow, and each growth is looked at again for both causes:
      // - a parting among those blocks' decisions that lies in ref's band too (the same clause and
      //   line, another branch in fast) is a knife edge of its own, and the blocks after it are its
      //   (campaign 20261225, case 399951: a touching crossing two blocks after a KONT knife edge);
      // - a look-ahead still searching at their end in either run is the knife edge's to its end:
      //   its search examines up to MD20240 blocks after the one that began it, and a deselection
      //   during it takes the strategy of TRC-EDGE-1 (campaign 20261320, case 276013: a collision
      //   check's cut inside the window ended fast's search, ref's went on into the deselection).
      for (bool grew = true; grew;) {
        grew = false;
        for (std::size_t k = ir_parted + 1; k < ir; ++k) {
          const Decision& d = ref.decisions[k];
          if (!in_band(d)) continue;
          bool same = false, other = false;
          for (std::size_t m = jf_parted; m < jf; ++m) {
            const Decision& e = fast.decisions[m];
            if (e.clause != d.clause || e.line != d.line) continue;
            (e.branch == d.branch ? same : other) = true;
          }
          if (same || !other) continue;
          std::optional<int> nested = reach(k, d.line);
          if (nested && *nested <= parted_upto) continue;
          knife.explanation += fmt::format("; then ref {} line {} {} (margin {}) in its band too", d.clause, d.line,
                                           d.branch, d.margin_exact);
          if (!nested) return knife;
          parted_upto = *nested, grew = true;
        }
        for (auto [run, end, engine] : {std::tuple{&ref, ir, "ref"}, std::tuple{&fast, jf, "fast"}}) {
          std::optional<int> began = searching_at(run->decisions, end);
          if (!began) continue;
          std::optional<int> until = reach(0, *began);
          if (until && *until <= parted_upto) continue;
          knife.explanation += fmt::format("; {}'s look-ahead from line {} still searching", engine, *began);
          if (!until) return knife;
          parted_upto = *until, grew = true;
        }
        if (grew) skip(ref.decisions, ir), skip(fast.decisions, jf);
      }
      // The runs part for good: a knife edge, as far as they can be compared.
      if (ir == ref.decisions.size() || jf == fast.decisions.size()) return knife;
      if (!same_decision(ref.decisions[ir], fast.decisions[jf])) return knife;
      resumed = ref.decisions[ir].line, resumed_at = ir;
      continue;
    }
    // fast's own crossing touches (its margin in the band) where ref found none to compare: an
    // entry exactly one point long in ref is nothing, a rounding longer in fast a sliver that may
    // touch a held piece (corpus cdon-entry-of-zero-length) or lie along one and overlap it
    // (corpus cdon-point-entry-along-a-held-piece); or fast hits where its carriers touch and
    // ref's point lies just off the piece (touching_hit).
    if (std::string_view touching = fast_touching(r, f, tol); !touching.empty()) {
      v.kind = Verdict::Kind::kKnifeEdge;
      v.clause = std::string(f.clause);
      v.explanation = where + ", " + std::string(touching);
      return v;
    }
    // After a knife edge only a touching decision since the runs met again explains a parting.
    if (parted_after_touching(ref, resumed_at, ir, tol, where, v)) return v;
    return diverge("unexplained " + where + fmt::format(", band {:.3g}", tol.band(r.clause)));
  }
  if (ir != ref.decisions.size() || jf != fast.decisions.size()) {
    if (resumed >= 0) return knife;  // one run went on after the knife edge where the other did not
    std::string where = fmt::format("ref took {} decisions, fast {}", ref.decisions.size(), fast.decisions.size());
    if (parted_after_touching(ref, 0, ir, tol, where, v)) return v;  // one run went on where the other did not
    return diverge(where);
  }
  // A crossing at a knife edge (touching a piece's end, or tangent: touching_crossing) is
  // ill-conditioned: the cut point moves by up to sqrt(band * size) and the cut may fall on either
  // piece at a joint, so what follows it is not compared coordinate by coordinate.
  for (const Decision& d : ref.decisions)
    if (touching_crossing(d, tol)) {
      v.kind = Verdict::Kind::kKnifeEdge;
      v.clause = std::string(d.clause);
      v.explanation = fmt::format("touching crossing at line {}", d.line);
      if (ref.alarms.size() != fast.alarms.size()) return diverge("different alarms after a touching crossing");
      return v;
    }
  if (resumed >= 0 && ref.alarms.size() != fast.alarms.size()) return knife;  // the runs end differently
  if (ref.alarms.size() != fast.alarms.size()) return diverge("different alarms");
  for (std::size_t i = 0; i < ref.alarms.size(); ++i)
    if (ref.alarms[i].number != fast.alarms[i].number || ref.alarms[i].line != fast.alarms[i].line)
      return diverge(fmt::format("alarm {} line {} vs {} line {}", ref.alarms[i].number, ref.alarms[i].line,
                                 fast.alarms[i].number, fast.alarms[i].line));
  // PATH-ELEMENT-1 writes no element of length zero; one shorter than the tolerance is zero for
  // one engine and a sliver for the other (a tool position one rounding off a programmed point, a
  // transition circle between two equidistants that meet within rounding): neither counts. An
  // arc is a sliver by its length along the circle (sweep × radius), never by its chord: a full
  // circle has a chord of 0.
  auto sliver = [&](const PathElement& e) {
    if (!(distance(e.start, e.end) <= tol.coordinate)) return false;
    if (e.type != ElementType::kArc) return true;
    std::optional<double> sweep = sweep_of(e);
    return sweep && *sweep * radius_of(e) <= tol.coordinate;
  };
  // PATH-ELEMENT-2 lets fast end a circle at its start when its true end lies within the error
  // of its points past it, at most 1e-8 of max(1 mm, the radius): where ref writes a whole turn
  // and then such a rest, fast may write the whole turn alone (campaign 20261216, case 106440: a
  // full circle opened 4.1e-8 mm before its normal start by an intersection at sine 2e-5).
  // After touching carriers (a decision in its band) the closing point is known only to within
  // Tolerance::touching: a rest that short is the knife edge's (campaign 20261223, case 721238:
  // a G461 retraction circle internally tangent to a full circle's equidistant at its end; fast's
  // hit lay 2.2e-6 mm past the start).
  const Decision* touch = nullptr;  // the first touching decision: coordinates within `touching`
  for (const Decision& d : ref.decisions)
    if (!touch && touching_carriers(d, tol)) touch = &d;
  const PathElement* rest_after_touching = nullptr;
  auto rest_after_whole_turn = [&](const PathElement& e, const PathElement* before) {
    if (!before || e.type != ElementType::kArc || before->type != ElementType::kArc) return false;
    bool whole =
        before->start.x == before->end.x && before->start.y == before->end.y && before->start.z == before->end.z;
    if (!whole || before->origin.line != e.origin.line || distance(before->center, e.center) != 0) return false;
    std::optional<double> sweep = sweep_of(e);
    double r = radius_of(e);
    if (!sweep) return false;
    if (*sweep * r <= 1e-8 * std::max(1.0, r)) return true;
    if (!touch || !(*sweep * r <= tol.touching)) return false;
    if (!rest_after_touching) rest_after_touching = &e;
    return true;
  };
  auto without_slivers = [&](const std::vector<PathElement>& path) {
    std::vector<const PathElement*> out;
    const PathElement* before = nullptr;
    for (const PathElement& e : path) {
      if (!sliver(e) && !rest_after_whole_turn(e, before)) out.push_back(&e);
      before = &e;
    }
    return out;
  };
  std::vector<const PathElement*> rp = without_slivers(ref.path), fp = without_slivers(fast.path);
  if (resumed >= 0) {  // PROP-DIFF-2: the paths from the block after the one where the runs met again
    auto after = [&](std::vector<const PathElement*>& path) {
      path.erase(path.begin(), std::find_if(path.begin(), path.end(),
                                            [&](const PathElement* e) { return e->origin.line > resumed; }));
    };
    after(rp), after(fp);
    v = knife;
    v.compared_after = true;
    v.explanation +=
        fmt::format("; the runs took the same branches again at line {} and are compared after it", resumed);
  }
  if (rp.size() != fp.size()) return diverge(fmt::format("ref output {} elements, fast {}", rp.size(), fp.size()));
  if (rest_after_touching && v.kind != Verdict::Kind::kKnifeEdge)
    v.kind = Verdict::Kind::kKnifeEdge, v.clause = std::string(touch->clause),
    v.explanation = fmt::format(
        "a rest of {} after a whole turn at line {}, after touching carriers at line {} "
        "(within {:.3g} mm)",
        describe(rest_after_touching->origin), rest_after_touching->origin.line, touch->line, tol.touching);
  for (std::size_t i = 0; i < rp.size(); ++i) {
    const PathElement& r = *rp[i];
    const PathElement& f = *fp[i];
    // The element's kind, what it comes from, its sense and whether it is a rapid, named where they differ.
    auto kind = [](const PathElement& e) {
      std::string k = e.type == ElementType::kArc ? (e.ccw ? "ccw arc" : "cw arc") : "line";
      return k + (e.rapid ? " rapid " : " ") + describe(e.origin);
    };
    if (r.type != f.type || r.origin.kind != f.origin.kind || r.origin.line != f.origin.line || r.rapid != f.rapid ||
        (r.type == ElementType::kArc && r.ccw != f.ccw))
      return diverge(fmt::format("element {}: {} vs {}", i, kind(r), kind(f)));
    // PROP-DIFF-3: what the element belongs to and how fast it runs are the blocks' data, decided
    // on programmed decimals: they never differ, knife edge or not.
    auto feed = [](const PathElement& e) {
      return e.feed.to_string() + (e.feed_type == FeedType::kG95   ? " (G95)"
                                   : e.feed_type == FeedType::kG93 ? " (G93)"
                                                                   : "");
    };
    if (r.feed != f.feed || r.feed_type != f.feed_type)
      return diverge(fmt::format("element {} ({}): feed {} vs {}", i, describe(r.origin), feed(r), feed(f)));
    // The whole origin, as the output names it: the block's number and place, the inserted element
    // it is, a transition circle's second corner block (its line, number and insert), the SAR move.
    if (r.origin != f.origin)
      return diverge(
          fmt::format("element {}: {} vs {} (what it belongs to)", i, describe(r.origin), describe(f.origin)));
    double e = std::max(distance(r.start, f.start), distance(r.end, f.end));
    if (r.type == ElementType::kArc) {
      e = std::max(e, distance(r.center, f.center));
      // The same end points, but one circle turning the other way round (a full circle against
      // a sliver): the difference along the circle counts.
      // Both about one axis where one qualifies for both: a helix whose start lies level with its
      // centre on a second axis, and whose end lies as far from the centre in that plane, leaves
      // two axes within rounding of a tie, which each engine's ulps may break differently or make
      // no tie at all (campaigns 20261259, case 64525, and 20261331, case 849333: SAR helices of
      // radius DISR = their drop). ref's axis where fast's start is level on it too, else fast's
      // where ref's is. (A full circle's points tell no axis: then each element's own.)
      bool r_full = r.start.x == r.end.x && r.start.y == r.end.y && r.start.z == r.end.z;
      int axis = r_full ? -1 : sweep_axis(r);
      if (axis >= 0 && !level_on(f, axis)) {
        int fast_axis = sweep_axis(f);
        if (fast_axis >= 0 && level_on(r, fast_axis)) axis = fast_axis;
      }
      std::optional<double> rs = sweep_of(r, axis), fs = sweep_of(f, axis);
      if (rs && fs) e = std::max(e, std::fabs(*rs - *fs) * radius_of(r));
      // A full circle (start == end) against an arc whose end points lie a rounding apart on one
      // radius: that arc's turn is undetermined (a sliver or a full circle to whoever reads it).
      bool f_full = f.start.x == f.end.x && f.start.y == f.end.y && f.start.z == f.end.z;
      if ((r_full && !fs) || (f_full && !rs))
        return diverge(
            fmt::format("element {} ({}): {} turns a full circle, {} writes end points that leave its "
                        "turn undetermined",
                        i, describe(r.origin), r_full ? "ref" : "fast", r_full ? "fast" : "ref"));
    }
    v.max_coordinate_error = std::max(v.max_coordinate_error, e);
    if (!(e <= tol.coordinate) && touch && e <= tol.touching) {
      if (v.kind != Verdict::Kind::kKnifeEdge)
        v.kind = Verdict::Kind::kKnifeEdge, v.clause = std::string(touch->clause),
        v.explanation = fmt::format(
            "element {} ({}) differs by {:.3g} mm after touching carriers at line {} "
            "(within {:.3g} mm)",
            i, describe(r.origin), e, touch->line, tol.touching);
      continue;
    }
    if (!(e <= tol.coordinate))
      return diverge(fmt::format("element {} ({}) differs by {:.3g} mm > tolerance {:.3g} mm", i, describe(r.origin), e,
                                 tol.coordinate));
  }
  if (ref.actions.size() != fast.actions.size()) return diverge("different actions");
  // PROP-DIFF-3: actions run where the tool is, SAR's variables are the tool's positions: the
  // same within the tolerance (after touching carriers, within the touching tolerance); after a
  // knife edge, those of the blocks after the line where the runs met again (PROP-DIFF-2).
  double at_most = touch && v.kind == Verdict::Kind::kKnifeEdge ? tol.touching : tol.coordinate;
  auto placed_apart = [&](int line, double e) { return (resumed < 0 || line > resumed) && !(e <= at_most); };
  for (std::size_t i = 0; i < ref.actions.size(); ++i) {
    const ActionEvent& r = ref.actions[i];
    const ActionEvent& f = fast.actions[i];
    if (r.line != f.line || r.function.name() != f.function.name())
      return diverge(fmt::format("action {}: {} at line {} vs {} at line {}", i, r.function.name(), r.line,
                                 f.function.name(), f.line));
    if (double e = distance(r.at, f.at); placed_apart(r.line, e))
      return diverge(fmt::format("action {} ({} at line {}) placed {:.3g} mm apart", i, r.function.name(), r.line, e));
  }
  if (ref.variables.size() != fast.variables.size()) return diverge("different SAR variables");
  for (std::size_t i = 0; i < ref.variables.size(); ++i) {
    const SarVariables& r = ref.variables[i];
    const SarVariables& f = fast.variables[i];
    double e = std::max(distance(r.p_apr, f.p_apr), distance(r.p_aep, f.p_aep));
    if (r.line != f.line || r.p_apdv != f.p_apdv || placed_apart(r.line, e))
      return diverge(fmt::format("SAR variables of line {}: $P_APR/$P_AEP {:.3g} mm apart, $P_APDV {} vs {}", r.line, e,
                                 r.p_apdv, f.p_apdv));
  }
  if (v.kind != Verdict::Kind::kKnifeEdge) {
    bool same = ref.notices.size() == fast.notices.size();
    for (std::size_t i = 0; same && i < ref.notices.size(); ++i)
      same = ref.notices[i].clause == fast.notices[i].clause && ref.notices[i].line == fast.notices[i].line;
    if (!same)
      return diverge(fmt::format("different notices ({} in ref, {} in fast)", ref.notices.size(), fast.notices.size()));
  }
  return v;
}

}  // namespace cutcom::props
