// Reading SINUMERIK NC text (spec NC-*): one line is one block. The reader turns text into
// BlockWords; the ProgramReader adds modal state, tool data and exact positions (Block).
// Both are streaming: a program of any length is read with bounded memory.
#pragma once

#include <istream>
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "cutcom/block.hpp"

namespace cutcom {

// Bad input: names the 1-based line and column and what is wrong. Exit status 2 in the CLI.
class InputError : public std::runtime_error {
 public:
  InputError(int line, int column, const std::string& what);
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& detail() const { return detail_; }

 private:
  int line_, column_;
  std::string detail_;
};

// Parses the words of one line (NC-LEX-*). Throws InputError.
void parse_block_words(std::string_view text, int line, BlockWords& out);

// Tool data set by $TC_DPn (TOOL-DATA-1).
struct EdgeData {
  Decimal type, position, radius, wear;  // $TC_DP1, $TC_DP2, $TC_DP6, $TC_DP15
};

// The control's tool table: edges by (T, D) and names by T (TOOL-DATA-1, TOOL-NAME-1).
class ToolTable {
 public:
  void assign(const ToolDataAssignment& a);
  void name(const ToolNameAssignment& a);
  const EdgeData* find(std::int64_t tool, std::int64_t edge) const;
  std::optional<std::int64_t> number_of(const std::string& name) const;
  // TOOL-FILE-1: a tool-offset archive (TO_INI.INI convention). Errors name the file and line.
  void load(std::istream& in, const std::string& source_name);

 private:
  std::map<std::pair<std::int64_t, std::int64_t>, EdgeData> edges_;
  std::map<std::string, std::int64_t> names_;
};

// Settable work offsets G54 … G599 (NC-OFFSET-1): a translation each, in mm.
class OffsetTable {
 public:
  void set(int index, int axis, Decimal value);
  Point3 translation(int index) const;
  bool defined(int index) const;
  // NC-OFFSET-2: $P_UIFR[n]=CTRANS(X,10,Y,20) or $P_UIFR[n,X,TR]=10 lines. Errors name file and line.
  void load(std::istream& in, const std::string& source_name);

 private:
  std::map<int, Point3> offsets_;
};

// A frame without rotation: base = offset + D·p + t per axis (NC-FRAME-2), D = ±scale.
struct AxisFrame {
  std::array<Decimal, 3> factor{Decimal::from_int(1), Decimal::from_int(1), Decimal::from_int(1)};
  std::array<Decimal, 3> shift{};
  bool identity() const;
};

// Reads blocks one by one and resolves modal state and positions (NC-MODAL-*, NC-POS-*).
class ProgramReader {
 public:
  explicit ProgramReader(std::istream& in, ModalState initial = {});
  // Next block, or false at the end of the text or after M2/M30. Throws InputError.
  bool next(Block& out);
  // SAR-END-3: after a SAR retraction without end point the tool is where the retraction ended;
  // blocks read after it start there (the engines give the in-plane position exactly).
  void set_position(const Point3& p) { position_ = p; }
  ToolTable& tools() { return tools_; }
  OffsetTable& offsets() { return offsets_; }
  const std::string& source_name() const { return source_; }
  void set_source_name(std::string name) { source_ = std::move(name); }

 private:
  void resolve(Block& b);
  void change_tool(Block& b, ModalState& s);
  void apply_frame(const BlockWords& w);
  Decimal to_base(int axis, const AxisWord& aw, const Decimal& current, bool absolute, bool distance = false) const;
  Decimal length(const Decimal& v) const;  // the unit of a programmed length
  void note(Block& b, std::string_view clause, std::string text);

  std::istream& in_;
  std::string text_;
  int line_ = 0;
  int index_ = 0;
  int end_line_ = 0;  // line of M2/M30, 0 before it
  ModalState state_;
  ModalState effective_;  // the last block's state as the engines see it (NC-FRAME-3)
  Point3 position_;
  ToolTable tools_;
  OffsetTable offsets_;
  std::string source_;
  // Tool preselected by T under MD22550 = 1, taking effect with M6 (TOOL-CHANGE-1).
  std::optional<std::int64_t> preselected_;
  Units units_ = Units::kG71;
  DiameterMode diameter_ = DiameterMode::kDiamof;
  int offset_index_ = 0;         // G500
  int first_offset_ = -1;        // the settable offset whose workpiece system the output uses
  AxisFrame frame_;              // programmable frame
  std::array<bool, 3> unknown_{};  // NC-CYCLE-1: axes whose position a cycle left unknown
  std::string unknown_after_;      // what left them unknown
  int unknown_line_ = 0;
  bool modal_call_ = false;
  std::string modal_cycle_;
};

}  // namespace cutcom
