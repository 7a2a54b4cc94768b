// Reading SINUMERIK NC text (spec NC-*): one line is one block. The reader turns text into
// BlockWords; the ProgramReader adds modal state, tool data and exact positions (Block).
// Both are streaming: a program of any length is read with bounded memory.
#pragma once

#include <istream>
#include <map>
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
  Decimal type, radius, wear;
};

class ToolTable {
 public:
  void assign(const ToolDataAssignment& a);
  const EdgeData* find(std::int64_t tool, std::int64_t edge) const;

 private:
  std::map<std::pair<std::int64_t, std::int64_t>, EdgeData> edges_;
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

 private:
  void resolve(Block& b);

  std::istream& in_;
  std::string text_;
  int line_ = 0;
  int index_ = 0;
  int end_line_ = 0;  // line of M2/M30, 0 before it
  ModalState state_;
  Point3 position_;
  ToolTable tools_;
};

}  // namespace cutcom
