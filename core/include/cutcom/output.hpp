// Writers of the output path model: text for people, JSON for programs (docs/json-format.md),
// SVG pictures of the programmed contour and the tool-centre path.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cutcom/sink.hpp"
#include "cutcom/spill_list.hpp"

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
  bool keeps_decisions() const override { return with_trace_; }
  void alarm(const Alarm& a) override;
  void notice(const Notice& n) override;
  void sar_variables(const SarVariables& v) override;
  // CLI-1: the run stopped on bad input; finish() still closes the document, with the error.
  void error(const std::string& file, int line, int column, const std::string& message);
  void finish();
  void set_sources(SourceNames names) { sources_ = std::move(names); }

 private:
  void written();  // writes the element buffer out once it is large
  // A number (the shortest text that reads back) and a point. Numbers written before are kept
  // with their text, one place per number chosen by its bits (a table of 256): numbers are most of
  // the writer's time, and an element starts where the one before it ended, mostly in the same
  // plane. A kept text is copied whole (kNumberCopy bytes): the buffer written has that room
  // past any number.
  static constexpr std::size_t kNumberCopy = 31;
  struct NumberText {
    std::uint64_t bits = 0;
    std::uint8_t size = 0;  // 0: none kept
    char text[kNumberCopy];
  };
  char* put_number(char* p, double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    NumberText& k = recent_[(bits * 0x9E3779B97F4A7C15u) >> 56];
    if (k.bits == bits && k.size != 0) {
      std::memcpy(p, k.text, kNumberCopy);
      return p + k.size;
    }
    return put_new_number(p, v, k);
  }
  char* put_new_number(char* p, double v, NumberText& keep);
  char* put_point(char* p, const PathPoint& q);
  std::array<NumberText, 256> recent_{};
  // The last element's end as written: the next one mostly starts there. Two texts: the
  // element being written keeps its end in the other one (its own buffer may be flushed).
  PathPoint last_end_{};
  char last_end_text_[2][3 * 26 + 4];
  std::size_t last_end_size_ = 0;
  int last_end_slot_ = 0;

  std::ostream& out_;
  SourceNames sources_;
  bool with_trace_;
  bool first_ = true;
  std::string buffer_;  // path elements not yet written
  std::string item_;    // an item of a list after the path (reused)
  Decimal last_feed_;   // the feed written last, and its JSON text
  std::string last_feed_text_;
  SpillList actions_, decisions_, alarms_, notices_, variables_;  // serialized JSON array items
  std::string error_;                                             // serialized object, if any
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
  bool keeps_decisions() const override { return with_trace_; }
  void alarm(const Alarm& a) override;
  void notice(const Notice& n) override;
  void sar_variables(const SarVariables& v) override;
  // CLI-1: the run stopped on bad input; finish() writes it as the last line.
  void error(const std::string& file, int line, int column, const std::string& message);
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
  std::string error_;
  // The last element's end and its text: the next element mostly starts there.
  PathPoint last_end_;
  char last_end_text_[96];
  std::size_t last_end_size_ = 0;  // 0: none kept
};

// A programmed contour segment for the picture (in-plane projection drawn as XY of the plane).
struct ProgrammedSegment {
  PathPoint start, end, center;
  bool arc = false, ccw = false, rapid = false;
  int line = 0;
  std::string label;  // its N number where the program has one ("N40"), else its line ("L12")
};

// The programmed contour of a program, block by block (a SAR block's contour is generated: drawn
// as path).
class ProgrammedContour {
 public:
  std::optional<ProgrammedSegment> add(const Block& b);  // none: the block draws nothing

 private:
  bool p4_pending_ = false;  // SAR-P4-2: the next traversing block's motion is the SAR element
};

// Bounds of what a picture keeps (issue "Performance" item 6).
struct PictureLimits {
  std::size_t full_elements = 20000;  // path elements (and programmed segments) drawn one by one
  std::size_t points = 200000;        // beyond: polylines of at most this many points in all
  std::size_t labels = 200;           // block labels kept in a reduced picture (every k-th)
  std::size_t markers = 2000;         // SAR P3/P4 markers drawn
};

// The SVG picture in memory bounded by PictureLimits, whatever the program length: up to
// `full_elements` every element is drawn with its arrow and title; beyond, the picture keeps
// polylines simplified within a bound it states on the picture (nothing is left out).
class SvgPicture : public PathSink {
 public:
  explicit SvgPicture(PictureLimits limits = {});
  ~SvgPicture() override;
  SvgPicture(const SvgPicture&) = delete;
  SvgPicture& operator=(const SvgPicture&) = delete;
  void programmed(const Block& b);  // the programmed contour, block by block, before the path
  void set_plane(Plane plane);      // the picture's plane (arcs of the path turn in it)
  void element(const PathElement& e) override;
  void alarm(const Alarm& a) override;
  void sar_variables(const SarVariables& v) override;
  bool keeps_decisions() const override { return false; }  // the picture draws no decisions
  void write(std::ostream& out, const std::string& title) const;
  const std::vector<Alarm>& alarms() const;
  bool reduced() const;
  double bound() const;  // mm: how far a drawn point may lie from the exact path (0: full detail)

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace cutcom
