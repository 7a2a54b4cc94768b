#include <fmt/format.h>

#include <cstring>

#include "cutcom/output.hpp"
#include "text_append.hpp"

namespace cutcom {

namespace {
// Written out when the buffer holds this much: few large writes instead of one per line.
constexpr std::size_t kFlushSize = 1 << 16;

// "(x, y, z)" with four decimals at `p` (room for 3 numbers of 352 characters); -0 prints as 0.
char* put_point(char* p, const PathPoint& point) {
  auto c = [](double v) { return v == 0 ? 0.0 : v; };
  *p++ = '(';
  p = text::put_fixed<4>(p, c(point.x));
  p = text::put(p, ", ");
  p = text::put_fixed<4>(p, c(point.y));
  p = text::put(p, ", ");
  p = text::put_fixed<4>(p, c(point.z));
  *p++ = ')';
  return p;
}

void append_point(std::string& out, const PathPoint& p) {
  char text[1100];
  out.append(text, put_point(text, p));
}

std::string pt(const PathPoint& p) {
  std::string s;
  append_point(s, p);
  return s;
}

const char* move_name(const PathElement& e) {
  if (e.rapid) return "rapid";
  if (e.feed_type == FeedType::kG95) return "feed/r";
  if (e.feed_type == FeedType::kG93) return "feed/t";
  return "feed";
}
}  // namespace

TextWriter::TextWriter(std::ostream& out, std::string engine, bool with_trace) : out_(out), with_trace_(with_trace) {
  buffer_.reserve(kFlushSize + 1024);
  buffer_ += fmt::format("cutcom tool-centre path (engine: {}, coordinates in mm)\n", engine);
  buffer_ +=
      fmt::format("{:>4} {:>5} {:<5} {:<6} {:<28} {:<28} {}\n", "#", "line", "type", "move", "start", "end", "origin");
}

TextWriter::~TextWriter() {
  try {
    flush();
  } catch (...) {  // a destructor must not throw; the stream's state reports the failure
  }
}

void TextWriter::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void TextWriter::written() {
  if (buffer_.size() >= kFlushSize) flush();
}

// The line is put together in a local array (bounded: two points of at most 3 x 352 characters)
// and appended at once: the writers emit millions of lines (issue "Performance").
void TextWriter::element(const PathElement& e) {
  ++count_;
  char line[3000];  // two points of huge numbers (3 x 352 characters each) and the description
  char* p = line;
  p = text::put_right_integer(p, count_, 4);
  *p++ = ' ';
  p = text::put_right_integer(p, e.origin.line, 5);
  *p++ = ' ';
  p = text::put(p, e.type == ElementType::kLine ? "line  " : (e.ccw ? "arc+  " : "arc-  "));
  char* field = p;
  p = text::put(p, move_name(e));
  p = text::put_padding(p, field, 6);
  *p++ = ' ';
  field = p;
  bool at_last_end = last_end_size_ != 0 && std::memcmp(&e.start, &last_end_, sizeof last_end_) == 0;
  p = at_last_end ? text::put(p, std::string_view(last_end_text_, last_end_size_)) : put_point(p, e.start);
  p = text::put_padding(p, field, 28);
  *p++ = ' ';
  field = p;
  p = put_point(p, e.end);
  auto end_size = static_cast<std::size_t>(p - field);
  last_end_size_ = end_size <= sizeof last_end_text_ ? end_size : 0;  // a huge number's text is not kept
  if (last_end_size_ != 0) std::memcpy(last_end_text_, field, end_size), last_end_ = e.end;
  p = text::put_padding(p, field, 28);
  *p++ = ' ';
  p = put_description(p, e.origin);
  std::string& b = buffer_;
  b.append(line, p);
  if (e.origin.source != 0 && sources_) {
    b += " (in ";
    b += sources_(e.origin.source);
    b += ')';
  }
  if (e.type == ElementType::kArc) {
    p = text::put(line, "  centre ");
    p = put_point(p, e.center);
    p = text::put(p, e.ccw ? " ccw\n" : " cw\n");
    b.append(line, p);
  } else {
    b += '\n';
  }
  written();
}

void TextWriter::action(const ActionEvent& a) {
  buffer_ += fmt::format("     {:>5} {} at {}\n", a.line, a.function.name(), pt(a.at));
  written();
}

void TextWriter::decision(const Decision& d) {
  if (!with_trace_) return;
  buffer_ += fmt::format("     trace line {:>4}  {:<16} {:<22}", d.line, d.clause, d.branch);
  if (d.has_margin)
    buffer_ += d.margin_exact.empty() ? fmt::format("  margin {:.6g}", d.margin) : "  margin " + d.margin_exact;
  buffer_ += '\n';
  written();
}

void TextWriter::alarm(const Alarm& a) {
  buffer_ += fmt::format("ALARM {} {}", a.number, a.text);
  if (a.source != 0 && sources_) buffer_ += " (in " + sources_(a.source) + ")";  // NC-PARAM-SUB-3
  buffer_ += fmt::format(" [{}]\n", a.clause);
  written();
}

void TextWriter::notice(const Notice& n) {
  buffer_ += fmt::format("note  line {}: {}", n.line, n.text);
  if (n.source != 0 && sources_) buffer_ += " (in " + sources_(n.source) + ")";  // NC-PARAM-SUB-3
  buffer_ += fmt::format(" [{}]\n", n.clause);
  written();
}

void TextWriter::sar_variables(const SarVariables& v) {
  buffer_ += fmt::format("     {:>5} $P_APR={} $P_AEP={} $P_APDV={}\n", v.line, pt(v.p_apr), pt(v.p_aep), v.p_apdv);
  written();
}

void TextWriter::error(const std::string& file, int line, int column, const std::string& message) {
  error_ = fmt::format("ERROR {} line {}, column {}: {}\n", file, line, column, message);
}

void TextWriter::finish() {
  buffer_ += error_;
  buffer_ += fmt::format("{} path elements\n", count_);
  flush();
}

}  // namespace cutcom
