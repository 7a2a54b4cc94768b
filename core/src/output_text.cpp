#include <fmt/format.h>

#include "cutcom/output.hpp"

namespace cutcom {

namespace {
std::string pt(const PathPoint& p) {
  auto c = [](double v) { return v == 0 ? 0.0 : v; };
  return fmt::format("({:.4f}, {:.4f}, {:.4f})", c(p.x), c(p.y), c(p.z));
}
}  // namespace

TextWriter::TextWriter(std::ostream& out, std::string engine, bool with_trace) : out_(out), with_trace_(with_trace) {
  out_ << fmt::format("cutcom tool-centre path (engine: {}, coordinates in mm)\n", engine);
  out_ << fmt::format("{:>4} {:>5} {:<5} {:<6} {:<28} {:<28} {}\n", "#", "line", "type", "move", "start", "end",
                      "origin");
}

void TextWriter::element(const PathElement& e) {
  ++count_;
  std::string type = e.type == ElementType::kLine ? "line" : (e.ccw ? "arc+" : "arc-");
  out_ << fmt::format("{:>4} {:>5} {:<5} {:<6} {:<28} {:<28} {}", count_, e.origin.line, type,
                      e.rapid                         ? "rapid"
                      : e.feed_type == FeedType::kG95 ? "feed/r"
                      : e.feed_type == FeedType::kG93 ? "feed/t"
                                                      : "feed",
                      pt(e.start), pt(e.end), describe(e.origin));
  if (e.origin.source != 0 && sources_) out_ << fmt::format(" (in {})", sources_(e.origin.source));
  if (e.type == ElementType::kArc) out_ << fmt::format("  centre {} {}", pt(e.center), e.ccw ? "ccw" : "cw");
  out_ << "\n";
}

void TextWriter::action(const ActionEvent& a) {
  out_ << fmt::format("     {:>5} {} at {}\n", a.line, a.function.name(), pt(a.at));
}

void TextWriter::decision(const Decision& d) {
  if (!with_trace_) return;
  out_ << fmt::format("     trace line {:>4}  {:<16} {:<22}", d.line, d.clause, d.branch);
  if (d.has_margin)
    out_ << (d.margin_exact.empty() ? fmt::format("  margin {:.6g}", d.margin) : "  margin " + d.margin_exact);
  out_ << "\n";
}

void TextWriter::alarm(const Alarm& a) { out_ << fmt::format("ALARM {} {} [{}]\n", a.number, a.text, a.clause); }

void TextWriter::notice(const Notice& n) { out_ << fmt::format("note  line {}: {} [{}]\n", n.line, n.text, n.clause); }

void TextWriter::sar_variables(const SarVariables& v) {
  out_ << fmt::format("     {:>5} $P_APR={} $P_AEP={} $P_APDV={}\n", v.line, pt(v.p_apr), pt(v.p_aep), v.p_apdv);
}

void TextWriter::finish() { out_ << fmt::format("{} path elements\n", count_); }

}  // namespace cutcom
