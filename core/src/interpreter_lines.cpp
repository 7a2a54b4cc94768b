// The interpreter's lines (interpreter.hpp): read from the program's file in large pieces or
// from the line cache, a unit's end at the next unit's header (NC-PARAM-SUB-8), and where the
// next line is read from.
#include <fstream>
#include <memory>
#include <string>
#include <string_view>

#include "cutcom/interpreter.hpp"
#include "interpreter_record.hpp"
#include "interpreter_text.hpp"
#include "word_lexer.hpp"

namespace cutcom {

using namespace interpreter_text;

bool Interpreter::getline(std::string& text) {
  std::string_view line;
  bool read = getline(line);
  if (line.data()) text.assign(line);  // a line was read (and perhaps given back)
  return read;
}

bool Interpreter::getline(std::string_view& text) {
  text = {};
  Context& c = cx();
  last_cached_ = nullptr;
  line_padded_ = false;
  c.line_start = c.offset;
  if (!c.cache->lines.empty()) {
    auto hit = c.cache->lines.find(c.offset);
    if (hit != c.cache->lines.end()) {
      last_cached_ = &hit->second;
      text = hit->second.text;
      c.offset = hit->second.next;
      ++c.line;
      return !unit_ends(c, text);
    }
  }
  if (!c.in) {  // a subprogram's file is opened when a line is first needed
    c.owned = std::make_unique<std::ifstream>(c.path);
    c.in = c.owned.get();
    c.stream_at = 0;
  }
  if (c.in == last_in_ && last_level_ != stack_.size()) c.stream_at = -1;  // another level read it
  last_in_ = c.in, last_level_ = stack_.size();
  if (c.stream_at != c.offset) {
    c.lines.reset(), c.in->clear();
    c.in->seekg(c.offset);
    if (!*c.in) throw InputError(c.line, 1, "a jump needs a program that can be read again (a file, not a pipe)");
  }
  if (!c.lines.next(*c.in, text)) {
    c.stream_at = -1;
    return false;
  }
  past_line_read(c, text);
  // NC-LEX-1: a file saved with a UTF-8 byte order mark (Windows editors) starts after it.
  if (c.line_start == 0 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (unit_ends(c, text)) return false;
  if ((control_flow_ || stack_.size() > 1) && cached_bytes_ + text.size() <= limits_.line_cache_bytes) {
    cached_bytes_ += text.size() + sizeof(CachedLine) + 32;  // with the table's own cost
    last_cached_ =
        &c.cache->lines.emplace(c.line_start, CachedLine{std::string(text), c.offset, nullptr}).first->second;
  }
  return true;
}

bool Interpreter::next_plain(BlockWords& plain, int& line) {
  if (stack_.size() != 1 || pending_next_ < pending_.size() || modal_call_due_ || control_flow_ || !macros_.empty() ||
      skip_levels_ != 0)
    return false;
  Context& c = stack_.front();
  // The file read on from where the last line ended, by this level; no cached line to take
  // instead, no section's end to see, no byte order mark to take off (at the text's start).
  if (!c.begun || c.offset == 0 || c.stream_at != c.offset || last_in_ != c.in || last_level_ != 1 ||
      !c.sections.empty() || !c.cache->lines.empty())
    return false;
  std::string_view view;
  if (!c.lines.next(*c.in, view)) return false;  // the end: next() sees it again
  // A line that begins with '%' or a blank may be a unit's header (unit_ends); an empty one has
  // no block.
  if (view.empty() || view[0] == '%' || view[0] == ' ' || view[0] == '\t') {
    c.lines.give_back(view);
    return false;
  }
  plain.reset(c.line + 1);
  if (!lexer::read_plain_block(view, plain, true)) {
    c.lines.give_back(view);
    return false;
  }
  // As getline() and next() leave a plain line.
  c.line_start = c.offset;
  past_line_read(c, view);
  line = c.line;
  last_cached_ = current_cached_ = nullptr;
  plain_refused_ = false;
  plain.plain = true;
  return true;
}

namespace {
// NC-PARAM-SUB-8: "%_N_NAME_SPF" or "%_N_NAME_MPF": the unit's name as written, or empty.
std::string_view unit_header(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  if (text.size() < 9 || text.substr(0, 4) != "%_N_") return {};
  std::string_view kind = text.substr(text.size() - 4);
  if (kind != "_SPF" && kind != "_MPF" && kind != "_spf" && kind != "_mpf") return {};
  return text.substr(1);
}
}  // namespace

// NC-PARAM-SUB-8: the header of another unit ends the text of the one being read (the line is
// given back); the unit's own header, before its first block, does not.
bool Interpreter::header_ends_unit(Context& c, std::string_view text) const {
  if (!c.begun) {
    std::size_t k = text.find_first_not_of(" \t\r");
    if (k == std::string::npos || text[k] == ';') return false;
    if (text[k] != '%') {
      c.begun = true;
      return false;
    }
  }
  if (text.empty() || (text[0] != '%' && text[0] != ' ' && text[0] != '\t') || c.line_start == c.header ||
      unit_header(text).empty())
    return false;
  if (!c.begun && c.header < 0) {
    c.header = c.line_start;
    return false;
  }
  c.offset = c.line_start;
  --c.line;
  c.stream_at = -1;
  return true;
}

// NC-PARAM-SUB-8: the units of the main program's text (a job archive, a file the control wrote
// with several programs: "%_N_MAIN_MPF" … "%_N_CONTOUR_SPF" …), found by their headers.
void Interpreter::scan_units() const {
  units_scanned_ = true;
  std::istream& in = *stack_.front().in;
  in.clear();
  if (!in.seekg(stack_.front().start_offset)) {  // a pipe: no units
    in.clear();
    return;
  }
  for (const Context& c : stack_)
    if (c.in == &in) c.stream_at = -1;  // every level reading it seeks first
  std::string text;
  std::streamoff at = stack_.front().start_offset;
  int line = 0;
  bool first = true;
  while (std::getline(in, text)) {
    std::string_view unit = unit_header(text);
    if (!unit.empty()) {
      std::string name = upper_text(unit.substr(3, unit.size() - 7));
      if (!first && !units_.try_emplace(name, SubprogramText{"", std::string(unit), at, line}).second)
        duplicate_units_.try_emplace(name, line + 1);  // the second header's line
      first = false;
    } else if (std::size_t k = text.find_first_not_of(" \t\r");
               first && k != std::string::npos && text[k] != ';' && text[k] != '%') {
      first = false;  // a block before any header: the main program has none
    }
    at += static_cast<std::streamoff>(text.size()) + 1;
    ++line;
  }
  in.clear();
}

void Interpreter::seek(std::streamoff to, int line) {
  cx().offset = to;
  cx().line = line;
}

}  // namespace cutcom
