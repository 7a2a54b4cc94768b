#include "compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cutcom::props {

namespace {
constexpr double kUnitRoundoff = 0x1p-53;

double margin_value(const Decision& d) {
  return d.margin_exact.empty() ? d.margin : std::strtod(d.margin_exact.c_str(), nullptr);
}

double distance(const PathPoint& a, const PathPoint& b) {
  return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}
}  // namespace

Conditioning conditioning_of(const std::vector<Block>& program) {
  Conditioning c;
  double prev_a = 0, prev_b = 0;
  bool have_prev = false;
  for (const Block& b : program) {
    PlaneAxes ax = plane_axes(b.state.plane);
    for (const Point3* p : {&b.start, &b.end})
      c.size =
          std::max({c.size, std::fabs(p->x.to_double()), std::fabs(p->y.to_double()), std::fabs(p->z.to_double())});
    c.radius = std::max(c.radius, std::fabs(b.state.effective_radius().to_double()));
    if (!b.moves_in_plane()) continue;
    double da = coord(b.end, ax.abscissa).to_double() - coord(b.start, ax.abscissa).to_double();
    double db = coord(b.end, ax.ordinate).to_double() - coord(b.start, ax.ordinate).to_double();
    double len = std::hypot(da, db);
    c.shortest = std::min(c.shortest, len);
    if (have_prev) {
      double cosine = (prev_a * da + prev_b * db) / (std::hypot(prev_a, prev_b) * len);
      c.corner = std::max(c.corner, 1 / std::max(1 + cosine, 1e-300));
    }
    prev_a = da, prev_b = db, have_prev = true;
  }
  c.size = std::max(c.size, c.radius);
  return c;
}

Tolerance Tolerance::for_program(const Conditioning& c) {
  Tolerance t;
  double leverage = c.size / c.shortest;  // how far a rounded input tilts the shortest direction
  t.coordinate = 64 * kUnitRoundoff * (c.size + c.radius * leverage * c.corner);
  t.sine = 16 * kUnitRoundoff * leverage;
  t.degrees = t.sine * 180 / 3.14159265358979323846;
  return t;
}

double Tolerance::band(std::string_view clause) const {
  if (clause == "TRC-CORNER-1") return sine;
  if (clause == "TRC-CORNER-3" || clause == "TRC-CORNER-4") return degrees;
  if (clause == "TRC-ELEMENT-1" || clause == "TRC-APPR-NORM-1" || clause == "TRC-RETR-NORM-1") return coordinate;
  return 0;  // decisions on exact decimals (block kinds, alarms) never diverge
}

Verdict compare(const RunResult& ref, const RunResult& fast, const Tolerance& tol) {
  Verdict v;
  auto diverge = [&](std::string why) {
    v.kind = Verdict::Kind::kDiverge;
    v.explanation = std::move(why);
    return v;
  };
  std::size_t n = std::min(ref.decisions.size(), fast.decisions.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Decision& r = ref.decisions[i];
    const Decision& f = fast.decisions[i];
    if (r.clause == f.clause && r.line == f.line && r.branch == f.branch) continue;
    std::string where = fmt::format("decision {}: ref {} line {} {} (margin {}), fast {} line {} {} (margin {})", i,
                                    r.clause, r.line, r.branch, r.margin_exact, f.clause, f.line, f.branch, f.margin);
    if (r.clause == f.clause && r.line == f.line && std::fabs(margin_value(r)) <= tol.band(r.clause)) {
      v.kind = Verdict::Kind::kKnifeEdge;  // legitimate: ref's margin lies inside the band
      v.explanation = where + fmt::format(", band {:.3g}", tol.band(r.clause));
      return v;
    }
    return diverge("unexplained " + where + fmt::format(", band {:.3g}", tol.band(r.clause)));
  }
  if (ref.decisions.size() != fast.decisions.size())
    return diverge(fmt::format("ref took {} decisions, fast {}", ref.decisions.size(), fast.decisions.size()));
  if (ref.alarms.size() != fast.alarms.size()) return diverge("different alarms");
  for (std::size_t i = 0; i < ref.alarms.size(); ++i)
    if (ref.alarms[i].number != fast.alarms[i].number || ref.alarms[i].line != fast.alarms[i].line)
      return diverge(fmt::format("alarm {} line {} vs {} line {}", ref.alarms[i].number, ref.alarms[i].line,
                                 fast.alarms[i].number, fast.alarms[i].line));
  if (ref.path.size() != fast.path.size())
    return diverge(fmt::format("ref output {} elements, fast {}", ref.path.size(), fast.path.size()));
  for (std::size_t i = 0; i < ref.path.size(); ++i) {
    const PathElement& r = ref.path[i];
    const PathElement& f = fast.path[i];
    if (r.type != f.type || r.origin.kind != f.origin.kind || r.origin.line != f.origin.line || r.rapid != f.rapid ||
        (r.type == ElementType::kArc && r.ccw != f.ccw))
      return diverge(fmt::format("element {}: {} vs {}", i, describe(r.origin), describe(f.origin)));
    double e = std::max(distance(r.start, f.start), distance(r.end, f.end));
    if (r.type == ElementType::kArc) e = std::max(e, distance(r.center, f.center));
    v.max_coordinate_error = std::max(v.max_coordinate_error, e);
    if (!(e <= tol.coordinate))
      return diverge(fmt::format("element {} ({}) differs by {:.3g} mm > tolerance {:.3g} mm", i, describe(r.origin), e,
                                 tol.coordinate));
  }
  if (ref.actions.size() != fast.actions.size()) return diverge("different actions");
  return v;
}

}  // namespace cutcom::props
