// PROP-META-*: metamorphic relations checked on ref's exact paths.
#include <fmt/format.h>

#include <sstream>

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

}  // namespace

std::string exact_image_mismatch(const std::string& original, const std::string& mapped, const MachineData& md,
                                 const AffineMap& map, int first_line, const MachineData* mapped_md) {
  ExactRun a = run_text(original, md), b = run_text(mapped, mapped_md ? *mapped_md : md);
  if (a.result.decisions.size() != b.result.decisions.size())
    return fmt::format("{} decisions against {}", a.result.decisions.size(), b.result.decisions.size());
  for (std::size_t i = 0; i < a.result.decisions.size(); ++i) {
    const Decision& x = a.result.decisions[i];
    const Decision& y = b.result.decisions[i];
    if (x.clause != y.clause || x.branch != y.branch || x.line != y.line)
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
