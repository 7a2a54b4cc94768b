// Writers of the output path model: text for people, JSON for programs (docs/json-format.md),
// SVG pictures of the programmed contour and the tool-centre path.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "cutcom/sink.hpp"

namespace cutcom {

// NC-PARAM-SUB-3: the text of an origin's `source` (where in a subprogram), from the reader.
using SourceNames = std::function<const std::string&(std::uint32_t)>;

// Streams path elements as they arrive; lists kept for the end (alarms, notices, trace).
class JsonWriter : public PathSink {
 public:
  JsonWriter(std::ostream& out, std::string engine, bool with_trace);
  void element(const PathElement& e) override;
  void action(const ActionEvent& a) override;
  void decision(const Decision& d) override;
  void alarm(const Alarm& a) override;
  void notice(const Notice& n) override;
  void sar_variables(const SarVariables& v) override;
  void finish();
  void set_sources(SourceNames names) { sources_ = std::move(names); }

 private:
  void written();  // writes the element buffer out once it is large

  std::ostream& out_;
  SourceNames sources_;
  bool with_trace_;
  bool first_ = true;
  std::string buffer_, text_;  // path elements not yet written; an origin's text (reused)
  std::string actions_, decisions_, alarms_, notices_, variables_;  // serialized JSON array items
};

class TextWriter : public PathSink {
 public:
  TextWriter(std::ostream& out, std::string engine, bool with_trace);
  ~TextWriter() override;
  TextWriter(const TextWriter&) = delete;
  TextWriter& operator=(const TextWriter&) = delete;
  void element(const PathElement& e) override;
  void action(const ActionEvent& a) override;
  void decision(const Decision& d) override;
  void alarm(const Alarm& a) override;
  void notice(const Notice& n) override;
  void sar_variables(const SarVariables& v) override;
  void finish();
  void set_sources(SourceNames names) { sources_ = std::move(names); }

 private:
  void written();  // writes the buffer out once it is large
  void flush();

  std::ostream& out_;
  std::string buffer_;  // text not yet written to out_
  SourceNames sources_;
  bool with_trace_;
  int count_ = 0;
};

// A programmed contour segment for the picture (in-plane projection drawn as XY of the plane).
struct ProgrammedSegment {
  PathPoint start, end, center;
  bool arc = false, ccw = false, rapid = false;
  int line = 0;
  std::string label;  // its N number where the program has one ("N40"), else its line ("L12")
};

void write_svg(std::ostream& out, const std::vector<ProgrammedSegment>& programmed, const RunResult& result,
               Plane plane, const std::string& title);

std::vector<ProgrammedSegment> programmed_contour(const std::vector<Block>& blocks);

}  // namespace cutcom
