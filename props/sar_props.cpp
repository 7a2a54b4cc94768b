// Properties of smooth approach and retraction (spec sar.md, PROP-SAR-*), on generated contours
// with SAR blocks at either end: the element's geometry, the infeed's monotony, the mirror of
// approach and retraction, the three ways of programming P4, and (in differential_props.cpp)
// fast against ref.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

struct V2 {
  double a, b;
};
V2 in_plane(const PathPoint& p, const PlaneAxes& ax) {
  auto pick = [&](int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; };
  return {pick(ax.abscissa), pick(ax.ordinate)};
}
double height(const PathPoint& p, const PlaneAxes& ax) {
  return ax.applicate == 0 ? p.x : ax.applicate == 1 ? p.y : p.z;
}
double len(V2 v) { return std::hypot(v.a, v.b); }
V2 sub(V2 p, V2 q) { return {p.a - q.a, p.b - q.b}; }
V2 unit(V2 v) {
  double l = len(v);
  return {v.a / l, v.b / l};
}

// The direction of travel of an output element where it starts / ends (in the plane, unit).
V2 direction(const PathElement& e, const PlaneAxes& ax, bool at_end) {
  if (e.type == ElementType::kLine) return unit(sub(in_plane(e.end, ax), in_plane(e.start, ax)));
  V2 r = sub(in_plane(at_end ? e.end : e.start, ax), in_plane(e.center, ax));
  double k = e.ccw ? 1 : -1;
  return unit({-k * r.b, k * r.a});
}

PlaneAxes axes_of(const ContourCase& c) {
  return plane_axes(c.plane == 17 ? Plane::kG17 : c.plane == 18 ? Plane::kG18 : Plane::kG19);
}

double mm(std::int64_t units, int decimals) { return static_cast<double>(units) * std::pow(10.0, -decimals); }

// covers: PROP-SAR-1 SAR-POINTS-1 SAR-DISR-1 SAR-DISR-2
RC_GTEST_PROP(SarProperty, ElementIsTangentAtP4AndFollowsDisr, ()) {
  ContourCase c = *sar_approach_only();
  CaseRuns r = run_case(c, false);
  if (r.ref_unsupported || !r.ref.alarms.empty() || r.ref.variables.empty()) {
    RC_TAG("alarm or not supported");
    return;
  }
  PlaneAxes ax = axes_of(c);
  V2 p3 = in_plane(r.ref.variables[0].p_apr, ax), p4 = in_plane(r.ref.variables[0].p_aep, ax);
  double eps = 1e-9 * std::max(1.0, len(p4) + len(p3));
  double radius = mm(c.radius_um, c.decimals), disr = mm(c.sar.disr_in, c.decimals);
  // SAR-DISR-1: the programmed line is DISR + r long (r only when positive).
  if (c.sar.contour_in == 147) RC_ASSERT(std::fabs(len(sub(p4, p3)) - (disr + std::max(radius, 0.0))) <= eps);
  std::size_t k = 0;
  while (k < r.ref.path.size() && r.ref.path[k].origin.sar != SarMove::kElement) ++k;
  if (k == r.ref.path.size()) {  // skipped by the look-ahead or cut away by collision detection
    RC_TAG("element removed");
    return;
  }
  const PathElement& el = r.ref.path[k];
  if (el.origin.kind == OriginKind::kInfeed) {  // its motion in the plane skipped: only the infeed is left
    RC_TAG("element removed");
    return;
  }
  // SAR-DISR-2: the tool centre runs on radius DISR; the programmed circle is a quadrant or a
  // semicircle through P3 and P4.
  if (c.sar.contour_in != 147) {
    RC_ASSERT(el.type == ElementType::kArc);
    RC_ASSERT(std::fabs(len(sub(in_plane(el.end, ax), in_plane(el.center, ax))) - disr) <= eps);
    double chord = len(sub(p4, p3)), big = c.sar.contour_in == 247 ? std::sqrt(2.0) : 2.0;
    RC_ASSERT(chord > 0);
    RC_ASSERT(std::fabs(chord / big - len(sub(in_plane(el.center, ax), p4))) <= eps);
  }
  // SAR-POINTS-1: tangent into the contour at P4, where the element ends at its normal end.
  if (std::fabs(len(sub(in_plane(el.end, ax), p4)) - std::fabs(radius)) > eps) {
    RC_TAG("element cut at its end");
    return;
  }
  std::size_t next = k + 1;
  while (next < r.ref.path.size() &&
         len(sub(in_plane(r.ref.path[next].end, ax), in_plane(r.ref.path[next].start, ax))) <= eps &&
         r.ref.path[next].type == ElementType::kLine)
    ++next;  // infeeds of blocks without motion in the plane
  if (next == r.ref.path.size()) return;
  // The contour's own equidistant must follow (not a cut by collision detection or a skip).
  const PathElement& after = r.ref.path[next];
  if (after.origin.kind != OriginKind::kOffset || after.origin.sar != SarMove::kNone) {
    RC_TAG("element followed by a cut or a skip");
    return;
  }
  V2 d1 = direction(el, ax, true), d2 = direction(r.ref.path[next], ax, false);
  RC_TAG("tangent checked");
  RC_ASSERT(d1.a * d2.a + d1.b * d2.b >= 1 - 1e-9);
  RC_ASSERT(std::fabs(d1.a * d2.b - d1.b * d2.a) <= 1e-6);
}

// covers: PROP-SAR-2 SAR-DISCL-1 SAR-DISCL-2 SAR-DISCL-3 SAR-SEG-1 SAR-SEG-2
RC_GTEST_PROP(SarProperty, InfeedIsMonotoneOrAlarm10741, ()) {
  ContourCase c = *sar_approach_only();
  c.plane_only = true;  // the heights are the SAR levels' alone
  CaseRuns r = run_case(c, false);
  if (r.ref_unsupported) return;
  // The levels, exactly, in units: h1 = h(P0), h4 = 0, h2 per SAR-DISCL-1/2.
  const SarEnds& s = c.sar;
  std::int64_t h1 = s.start_h, h4 = 0, h2 = s.discl_in ? s.discl_in_v : h1;
  if (s.seg_in == 340 && (!s.discl_in || (!s.discl_in_ac && s.discl_in_v == 0))) h2 = h1;
  std::int64_t lo = std::min(h1, h4), hi = std::max(h1, h4);
  std::int64_t excess = h2 < lo ? lo - h2 : h2 > hi ? h2 - hi : 0;
  const std::int64_t tol = 10;  // MD20204 = 0.01 mm in um
  bool reversal = excess > tol;
  RC_TAG(excess == 0     ? "between"
         : excess < tol  ? "clamped inside"
         : excess == tol ? "clamped on the bound"
                         : "reversal");
  bool alarm10741 = !r.ref.alarms.empty() && r.ref.alarms[0].number == 10741;
  // An earlier alarm (10742 for DISR, 10744 for G143 on the tangent; 10740, too many blocks
  // without plane motion before P4 is known) comes before the check.
  bool earlier = !r.ref.alarms.empty() && !alarm10741 && (r.ref.alarms[0].line == 4 || r.ref.alarms[0].number == 10740);
  if (earlier) return;
  RC_ASSERT(alarm10741 == reversal);
  if (reversal) return;
  // The applicates of the SAR block's sub-movements up to P4 run one way only.
  PlaneAxes ax = axes_of(c);
  double prev = mm(h1, c.decimals), dir = 0;
  for (const PathElement& e : r.ref.path) {
    if (e.origin.sar == SarMove::kNone || e.origin.line > 5) continue;
    for (double z : {height(e.start, ax), height(e.end, ax)}) {
      double d = z - prev;
      if (std::fabs(d) > 1e-12) {
        RC_ASSERT(dir * d >= 0);
        dir = d > 0 ? 1 : -1;
      }
      prev = z;
    }
    if (e.origin.sar == SarMove::kElement) break;
  }
}

// The same contour backwards with the approach turned into a retraction (SAR-POINTS-2, decision
// 14): compensation side swapped, G141 <-> G142, the start position the retraction's end point.
ContourCase mirrored(const ContourCase& c) {
  ContourCase r = reversed_contour(c);
  SarEnds& m = r.sar;
  m.approach = false, m.retraction = true;
  m.contour_out = c.sar.contour_in + 1;
  m.side_out = c.sar.side_in == 141 ? 142 : c.sar.side_in == 142 ? 141 : c.sar.side_in;
  m.seg_out = c.sar.seg_in, m.disr_out = c.sar.disr_in;
  m.discl_out = c.sar.discl_in, m.discl_out_ac = c.sar.discl_in_ac, m.discl_out_v = c.sar.discl_in_v;
  m.end_case = 3, m.end_h = c.sar.start_h, m.deselect = true;
  return r;
}

// covers: PROP-SAR-3 SAR-POINTS-2 SAR-END-1
RC_GTEST_PROP(SarProperty, ApproachAndRetractionAreMirrorImages, ()) {
  ContourCase c = *sar_approach_only();
  c.sar.p4_mode = 0, c.sar.fad_in = false;
  c.kont_select = c.kont_deselect = false;  // NORM both ways: KONT has its own mirror property
  c.g451_select = c.g451_deselect = false, c.cdon = false;
  for (Step& s : c.steps) s.dummies = 0, s.flip = s.again = false, s.g451 = false;
  c.plane_only = true;
  ContourCase m = mirrored(c);
  RC_LOG() << "mirrored program:\n" << to_program(m) << "\n";
  CaseRuns a = run_case(c, false), b = run_case(m, false);
  if (a.ref_unsupported || b.ref_unsupported || !a.ref.alarms.empty() || !b.ref.alarms.empty()) {
    RC_TAG("alarm or not supported");
    return;
  }
  // The look-ahead is not mirror-symmetric (TRC-LOOK-1 asks whether the *later* block reaches the
  // intersection), nor are the strategies it leads to: compare where neither run needed it.
  for (const CaseRuns* x : {&a, &b})
    for (const Decision& d : x->ref.decisions)
      if ((d.clause == "TRC-LOOK-1" && d.branch == "too-short") || d.clause == "TRC-EDGE-1") {
        RC_TAG("look-ahead");
        return;
      }
  int sar_in = 4, sar_out = 5 + static_cast<int>(m.steps.size());
  std::vector<PathElement> in, out;
  for (const PathElement& e : a.ref.path)
    if (e.origin.line == sar_in) in.push_back(e);
  for (const PathElement& e : b.ref.path)
    if (e.origin.line == sar_out) out.push_back(e);
  RC_ASSERT(in.size() == out.size());
  double eps = 1e-9 * (1 + a.tolerance.coordinate * 1e9);
  auto near = [&](const PathPoint& p, const PathPoint& q) {
    return std::fabs(p.x - q.x) <= eps && std::fabs(p.y - q.y) <= eps && std::fabs(p.z - q.z) <= eps;
  };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const PathElement& e = in[i];
    const PathElement& f = out[out.size() - 1 - i];
    RC_ASSERT(e.type == f.type);
    RC_ASSERT(near(e.start, f.end));
    RC_ASSERT(near(e.end, f.start));
    if (e.type == ElementType::kArc) {
      RC_ASSERT(e.ccw != f.ccw);
      PlaneAxes ax = axes_of(c);
      RC_ASSERT(std::fabs(len(sub(in_plane(e.center, ax), in_plane(f.center, ax)))) <= eps);
    }
  }
  RC_TAG("compared");
}

// covers: PROP-SAR-4 SAR-P4-1 SAR-P4-2
RC_GTEST_PROP(SarProperty, ThreeWaysToProgramP4GiveTheSamePath, ()) {
  ContourCase c = *sar_approach_only();
  // A block that does not move in the plane cannot give P4 (SAR-P4-1): start off the first point.
  if (c.start_x == c.first_x && c.start_y == c.first_y) c.start_x += 1000;
  CaseRuns runs[3];
  for (int mode = 0; mode < 3; ++mode) {
    c.sar.p4_mode = mode;
    runs[mode] = run_case(c, false);
  }
  if (runs[0].ref_unsupported) {  // TRC-UNSUP-1: then in every variant (lines after N20 one later)
    RC_TAG("not supported");
    for (int mode = 1; mode < 3; ++mode)
      RC_ASSERT(runs[mode].ref_unsupported == runs[0].ref_unsupported ||
                runs[mode].ref_unsupported == runs[0].ref_unsupported + 1);
    return;
  }
  for (int mode = 1; mode < 3; ++mode)
    for (const auto& [x, y] : {std::pair{&runs[0].ref, &runs[mode].ref}, std::pair{&runs[0].fast, &runs[mode].fast}}) {
      RC_ASSERT(runs[0].ref_unsupported == 0);
      RC_ASSERT(x->alarms.size() == y->alarms.size());
      for (std::size_t i = 0; i < x->alarms.size(); ++i) RC_ASSERT(x->alarms[i].number == y->alarms[i].number);
      RC_ASSERT(x->path.size() == y->path.size());
      for (std::size_t i = 0; i < x->path.size(); ++i) {
        const PathElement& e = x->path[i];
        const PathElement& f = y->path[i];
        RC_ASSERT(e.type == f.type && e.rapid == f.rapid && e.feed == f.feed);
        for (const auto& [p, q] : {std::pair{e.start, f.start}, std::pair{e.end, f.end}, std::pair{e.center, f.center}})
          RC_ASSERT(p.x == q.x && p.y == q.y && p.z == q.z);
      }
    }
  RC_TAG(runs[0].ref.alarms.empty() ? "no alarm" : "alarm " + std::to_string(runs[0].ref.alarms[0].number));
}

}  // namespace
}  // namespace cutcom::props
