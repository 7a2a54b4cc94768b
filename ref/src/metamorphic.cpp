// PROP-META-*: metamorphic relations checked on ref's exact paths.
#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <string_view>

#include "cutcom/ref/exact_checks.hpp"
#include "exact_path.hpp"

namespace cutcom::ref {

namespace {

struct ExactRun {
  RunResult result;
  ExactPath path;
};

ExactRun run_text(const std::string& text, const MachineData& md) {
  ExactRun r;
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  CollectingSink sink;
  run_exact(reader, md, sink, r.path);
  r.result = std::move(sink.result);
  return r;
}

ExactPoint image(const ExactPoint& p, const AffineMap& map) {
  const FT* c[3] = {&p.x, &p.y, &p.z};
  FT out[3];
  for (int i = 0; i < 3; ++i) {
    FT sum(0);
    for (int j = 0; j < 3; ++j)
      if (map.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] != 0)
        sum = sum + FT(map.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]) * *c[j];
    out[i] = sum / FT(map.denominator) + leaf(map.offset[static_cast<std::size_t>(i)]);
  }
  return {out[0], out[1], out[2]};
}

bool equal(const ExactPoint& a, const ExactPoint& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool reflects(const AffineMap& map) {
  const auto& m = map.m;
  long det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return det < 0;
}

// SAR-SIDE-1/2 name the side of the contour's tangent: a reflection swaps left and right (and
// G141/G142, which a mirroring frame swaps too: NC-FRAME-3). Other branches are relative to the
// contour (inner, outer, ...) and stay.
std::string image_branch(std::string_view clause, std::string_view branch, bool reflected) {
  std::string b(branch);
  if (!reflected || clause.substr(0, 8) != "SAR-SIDE") return b;
  auto swap = [&b](std::string_view x, std::string_view y) {
    if (auto at = b.find(x); at != std::string::npos) return b.replace(at, x.size(), y), true;
    if (auto at = b.find(y); at != std::string::npos) return b.replace(at, y.size(), x), true;
    return false;
  };
  swap("left", "right");
  swap("G141", "G142");
  return b;
}

}  // namespace

std::string exact_image_mismatch(const std::string& original, const std::string& mapped, const MachineData& md,
                                 const AffineMap& map, int first_line, const MachineData* mapped_md) {
  ExactRun a = run_text(original, md), b = run_text(mapped, mapped_md ? *mapped_md : md);
  if (a.result.decisions.size() != b.result.decisions.size())
    return fmt::format("{} decisions against {}", a.result.decisions.size(), b.result.decisions.size());
  for (std::size_t i = 0; i < a.result.decisions.size(); ++i) {
    const Decision& x = a.result.decisions[i];
    const Decision& y = b.result.decisions[i];
    if (x.clause != y.clause || image_branch(x.clause, x.branch, reflects(map)) != y.branch || x.line != y.line)
      return fmt::format("decision {}: {} {} line {} against {} {} line {}", i, x.clause, x.branch, x.line, y.clause,
                         y.branch, y.line);
  }
  if (a.result.alarms.size() != b.result.alarms.size()) return "different alarms";
  auto compared = [first_line](const ExactPath& p) {
    std::vector<const ExactPath::Element*> out;
    for (const auto& e : p.elements())
      if (e.line >= first_line) out.push_back(&e);
    return out;
  };
  auto pa = compared(a.path), pb = compared(b.path);
  if (pa.size() != pb.size()) return fmt::format("{} elements against {}", pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const ExactPath::Element& x = *pa[i];
    const ExactPath::Element& y = *pb[i];
    if (x.centre.has_value() != y.centre.has_value()) return fmt::format("element {}: kind differs", i);
    if (!equal(image(x.start, map), y.start)) return fmt::format("element {}: start is not the image", i);
    if (!equal(image(x.end, map), y.end)) return fmt::format("element {}: end is not the image", i);
    if (x.centre && !equal(image(*x.centre, map), *y.centre))
      return fmt::format("element {}: centre is not the image", i);
  }
  return "";
}

}  // namespace cutcom::ref

namespace cutcom::ref {

namespace {
// The elements of the move onto the contour (approach line, KONT circle) or off it.
std::vector<const ExactPath::Element*> end_part(const ExactRun& r, bool approach, int selection_line,
                                                int deselection_line) {
  std::vector<const ExactPath::Element*> out;
  for (std::size_t i = 0; i < r.result.path.size(); ++i) {
    const Origin& o = r.result.path[i].origin;
    bool take = approach ? o.kind == OriginKind::kApproach ||
                               (o.kind == OriginKind::kTransitionCircle && o.line == selection_line)
                         : o.kind == OriginKind::kRetraction ||
                               (o.kind == OriginKind::kTransitionCircle && o.next_line == deselection_line);
    if (take) out.push_back(&r.path.elements()[i]);
  }
  return out;
}

std::string mirrored(const std::vector<const ExactPath::Element*>& a, const std::vector<const ExactPath::Element*>& b,
                     const char* what) {
  if (a.size() != b.size()) return fmt::format("{}: {} elements against {}", what, a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const ExactPath::Element& x = *a[i];
    const ExactPath::Element& y = *b[a.size() - 1 - i];
    if (!equal(x.start, y.end) || !equal(x.end, y.start)) return fmt::format("{}: element {} is not reversed", what, i);
    if (x.centre.has_value() != y.centre.has_value() || (x.centre && !equal(*x.centre, *y.centre)))
      return fmt::format("{}: element {} has another centre", what, i);
  }
  return "";
}
}  // namespace

std::optional<std::string> exact_reversal_mismatch(const std::string& original, const std::string& reversed,
                                                   const MachineData& md, int selection_line, int deselection_line) {
  ExactRun a = run_text(original, md), b = run_text(reversed, md);
  if (a.result.path.size() != a.path.elements().size() || b.result.path.size() != b.path.elements().size())
    return std::string("output and exact path differ in length");
  if (!a.result.alarms.empty() || !b.result.alarms.empty()) return std::nullopt;
  // The predictive calculation searches forwards: where the two runs pass over different blocks
  // (mapped line L <-> selection + deselection - L), the ends are not comparable.
  auto skipped = [](const ExactRun& r, int flip) {
    std::vector<int> lines;
    for (const Decision& d : r.result.decisions)
      if (d.clause == "TRC-LOOK-3") lines.push_back(flip ? flip - d.line : d.line);
    std::sort(lines.begin(), lines.end());
    return lines;
  };
  if (skipped(a, 0) != skipped(b, selection_line + deselection_line)) return std::nullopt;
  std::string why = mirrored(end_part(a, true, selection_line, deselection_line),
                             end_part(b, false, selection_line, deselection_line), "approach / reversed retraction");
  if (!why.empty()) return why;
  return mirrored(end_part(a, false, selection_line, deselection_line),
                  end_part(b, true, selection_line, deselection_line), "retraction / reversed approach");
}

}  // namespace cutcom::ref
