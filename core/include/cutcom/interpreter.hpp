// The interpreter layer of the NC language (spec nc-parametric.md, NC-PARAM-*): between the text
// and the block reader. It keeps R parameters and user variables, evaluates expressions, runs
// control flow (labels, jumps, IF/ELSE, loops) and hands the reader plain blocks: every value
// written as a decimal on the 10^-9 grid (NC-PARAM-GRID-1). A program without any of it passes
// through unchanged, line by line: memory stays bounded whatever the program length.
#pragma once

#include <cstdint>
#include <istream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "cutcom/input_error.hpp"
#include "cutcom/line_buffer.hpp"

namespace cutcom {

class InterpreterLookup;
struct BlockWords;
struct LineRecord;  // interpreter_record.hpp
struct LineRecordDeleter {
  void operator()(LineRecord* r) const;
};

// A value of the NC language: REAL (binary64, as the control computes), INT, BOOL, STRING or
// FRAME.
struct NcValue {
  enum class Type { kReal, kInt, kBool, kString, kFrame } type = Type::kReal;
  double number = 0;  // REAL, INT (whole), BOOL (0 or 1)
  // STRING, AXIS names; FRAME: its chain as the reader's additive frame blocks, one per line
  // ("ATRANS X10", "AROT Z30", …; empty: the identity), NC-PARAM-FRAME-1.
  std::string text;
  static NcValue real(double v) { return {Type::kReal, v, {}}; }
  static NcValue integer(double v) { return {Type::kInt, v, {}}; }  // whole, within kIntMin…kIntMax
  // NC-PARAM-TYPE-1: INT is a 32-bit integer with sign.
  static constexpr double kIntMin = -2147483648.0, kIntMax = 2147483647.0;
  static bool fits_int(double v) { return v >= kIntMin && v <= kIntMax; }
  static NcValue boolean(bool v) { return {Type::kBool, v ? 1.0 : 0.0, {}}; }
  static NcValue string(std::string s) { return {Type::kString, 0, std::move(s)}; }
  static NcValue frame(std::string chain) { return {Type::kFrame, 0, std::move(chain)}; }
};

// What the interpreter reads from the machine's state (system variables, NC-PARAM-SYS-1):
// implemented by the ProgramReader, which knows the tool in force and the position.
class SystemValues {
 public:
  virtual ~SystemValues() = default;
  // The value of `name` (upper case, with its '$') with the given indices (an axis index is
  // given as 0 X, 1 Y, 2 Z); empty if the variable is not known to cutcom.
  virtual std::optional<double> system_value(std::string_view name, const std::vector<NcValue>& indices) = 0;
  // NC-PARAM-SUB-4, PROC … SAVE: the modal state when the subprogram starts is kept, and put back
  // when it returns (every block before has been read by then).
  virtual void save_modal_state() {}
  // NC-PARAM-SYS-2: "$P_UIFR[n]=CTRANS(X,10,Y,20)" or "$P_UIFR[n,X,TR]=10" with values on the
  // grid; false: not taken. Throws InputError (column 1) for a wrong assignment.
  virtual bool write_settable_offset(const std::string& /*assignment*/) { return false; }
  // NC-PARAM-SYS-5: $P_IFRAME=… : the settable frame in force becomes the assignment's frame
  // (written "$P_UIFR[1]=CTRANS(…)" or "$P_UIFR[1,X,TR]=10" for the frame in force); false: not taken.
  virtual bool write_settable_frame(const std::string& /*assignment*/) { return false; }
  // NC-PARAM-FRAME-1: the programmable frame in force, as frame blocks the reader reads back to
  // the same frame ("TRANS X1 Y2\nAROT Z30\nASCALE X-1"); empty if not known.
  virtual std::optional<std::string> programmable_frame() { return std::nullopt; }
  // NC-PARAM-FRAME-2: the programmable frame with one component (axis 0 X, 1 Y, 2 Z; "TR", "FI",
  // "RT", "SC" or "MI") set to `value` (grid text), written as programmable_frame() writes it.
  // Throws InputError (column 1) for a value the frame cannot hold.
  virtual std::optional<std::string> programmable_frame_with(int /*axis*/, std::string_view /*component*/,
                                                             std::string_view /*value*/) {
    return std::nullopt;
  }
  // NC-PARAM-SYS-1: $TC_TP2[tool], the tool's name; empty if it has none.
  virtual std::optional<std::string> tool_name(double /*tool*/) { return std::nullopt; }
  // NC-PARAM-FRAME-2: settable offset n (0: the one in force) as a frame value; empty if unknown.
  virtual std::optional<std::string> settable_frame(int /*n*/) { return std::nullopt; }
  virtual void restore_modal_state() {}
};

struct InterpreterLimits {
  // NC-PARAM-FLOW-6: jumps back (loop passes and backward GOTOs) before a program is taken as
  // running away.
  std::int64_t max_backward_jumps = 1'000'000;
  // Text of program lines kept in memory for loops and calls to read again (all files together).
  std::size_t line_cache_bytes = std::size_t{16} << 20;
};

class Interpreter {
 public:
  Interpreter(std::istream& in, SystemValues* system = nullptr, InterpreterLimits limits = {});

  // The next block's text for the reader and its line in the file; false at the end of the
  // text. Throws InputError naming the line and column.
  // With `plain`, a line of the main program that read_plain_block reads whole (N, G0…G3, X Y Z,
  // I J K, F with plain decimals) is read into it at once, as parse_block_words would read it,
  // and `plain->plain` tells so (`text` is then left as it was: the words are the line); such a
  // line holds no name, '=' or ':', so it has nothing for the interpreter to do and is not
  // scanned for it, nor copied (issue "Performance": one pass over the line).
  bool next(std::string& text, int& line, BlockWords* plain = nullptr);
  // The same for the common line alone (issue "Performance": the layers of next() around it
  // were a sixth of the reader's work): the main program's next line, straight from its file,
  // where nothing is in force that next() would look at (a frame assignment's blocks, a modal
  // call, control flow, a repeated section, macros, skip levels, a unit's header) and that
  // read_plain_block reads whole. False where it is not that line: it is then left to next().
  bool next_plain(BlockWords& plain, int& line);
  // After next() gave `text`: read_plain_block has refused that very text (a line of other
  // words, returned as it stands), so the word lexer need not try it again.
  bool plain_refused() const { return plain_refused_; }

  void set_limits(InterpreterLimits limits) { limits_ = limits; }
  // NC-WORD-2: the skip levels the operator has switched on, bit n for `/n` (`/` is `/0`).
  void set_skip_levels(std::uint16_t levels) { skip_levels_ = levels; }
  // NC-PARAM-SUB-1: where subprograms are looked for (the program's folder first).
  // NC-CYCLE-3: a call of one of these that no file answers is left to the block reader.
  void set_machine_cycles(std::vector<std::string> names) { machine_cycles_ = std::move(names); }
  void set_search_path(std::vector<std::string> dirs) {
    search_path_ = std::move(dirs);
    subprogram_files_ = true;
    found_.clear();
  }
  // No file is a subprogram (a program given as text, as in a campaign or a fuzz target: its
  // words never depend on the files of the current folder).
  void no_subprogram_files() {
    subprogram_files_ = false;
    found_.clear();
  }
  // NC-PARAM-VAR-3: a definitions file (GUD, DEF.DIR/*.DEF): its DEF lines make variables every
  // program level sees. Errors name the line of that file.
  void load_definitions(std::istream& in);
  // NC-PARAM-SUB-5: the program is a subprogram run on its own with these arguments ("5, 2.5, , 1"),
  // as if called with them.
  void set_arguments(std::string_view list);
  // NC-PARAM-SYS-4: machine and setting data a program may read ($MC_…, $MN_…, $SC_…), by name
  // with its index ("$MN_AXCONF_MACHAX_NAME_TAB[0]") and the value's text (a number or "text").
  void set_machine_values(const std::map<std::string, std::string>& values);
  // NC-PARAM-SUB-6: the reader read a block that moves; a modal call (MCALL) of this level runs
  // its subprogram before the next block.
  void block_moved() {
    if (modal_call_ && stack_.size() == modal_call_->level) modal_call_due_ = true;
  }
  // NC-PARAM-SUB-3: an id for where the block just returned stands in its subprogram and the
  // subprograms that called it (0: in the main program); the same place keeps its id.
  std::uint32_t block_source();
  const std::string& source_text(std::uint32_t id) const { return source_names_[id < source_names_.size() ? id : 0]; }
  bool in_subprogram() const { return stack_.size() > 1; }
  int current_line() const { return cx().line; }  // in the file being read
  // An error found in a subprogram's block, named with its file, line and calls (NC-PARAM-SUB-3).
  InputError where(const InputError& e) const;
  // A label, a jump or a structure was met: blocks after M2/M30 are then jump targets, not an error.
  bool uses_control_flow() const { return control_flow_; }

  // Exposed for tests: evaluates an expression in the current variables.
  NcValue evaluate(std::string_view expression, int line = 0);

  struct Variable {
    NcValue::Type type = NcValue::Type::kReal;
    std::vector<int> dims;  // empty: a scalar
    std::vector<NcValue> values;
  };

 private:
  struct Frame {  // an open loop (NC-PARAM-FLOW-3/4)
    enum class Kind { kWhile, kFor, kLoop, kRepeat } kind;
    std::streamoff body;   // where its body starts (WHILE: its own line, decided again)
    int body_line;         // the number of lines before that position
    std::string variable;  // FOR: the counter
    double end = 0;        // FOR: the last value
    int open_line = 0;     // the line of its opening word
  };

  bool getline(std::string& text);
  // The same without a copy: `text` holds until the next line is read.
  bool getline(std::string_view& text);
  // Sets where the next line is read; the stream itself is moved only when a line must be read
  // from it (a loop's body is read again from the line cache).
  void seek(std::streamoff to, int line);

  // Lines of a program file by their offset, kept once the program runs control flow or
  // subprograms: a loop pass or a call reads them from memory, not from the file again. All
  // caches together hold at most InterpreterLimits::line_cache_bytes; lines past that are read
  // from the file.
  struct CachedLine {
    std::string text;
    std::streamoff next;  // offset of the line after it
    // NC-PARAM-EXPR-4: its expressions as recorded when the line first ran, and, for a line of
    // assignments and words, its plan (interpreter_record.hpp).
    std::unique_ptr<LineRecord, LineRecordDeleter> record;
  };
  CachedLine* last_cached_ = nullptr;     // the cached line getline() returned last (or null)
  bool line_padded_ = false;              // getline()'s last line lies in a LineBuffer (its padding)
  bool plain_refused_ = false;            // plain_refused()
  CachedLine* current_cached_ = nullptr;  // the line next() runs, if it is cached
  LineRecord& record_of(CachedLine& line);
  // An expression of the line being run, from `from`: evaluated from its record when the line
  // ran before, else parsed (and recorded when the line is cached). `end`: where it ends;
  // `recorded`: its index in the line's record, or -1.
  NcValue expression(std::string_view s, std::size_t from, InterpreterLookup& lookup, std::size_t& end,
                     int* recorded = nullptr);
  // The values of a recorded expression's variables, each a scalar of the running level or a
  // global; false if one is not (the line then runs from its text).
  bool resolve(const std::vector<std::string>& names, std::vector<Variable*>& into);
  // Changes whenever a variable is made or dropped (DEF, a call's parameters, a return): what
  // records resolved before is looked up again.
  std::uint64_t variables_epoch_ = 0;
  // Runs the line from its plan; false if the plan does not apply (nothing has been done then).
  bool run_plan(LineRecord& record, std::string& out);
  struct LineCache {
    std::unordered_map<std::streamoff, CachedLine> lines;
  };
  std::map<std::string, LineCache> line_caches_;  // by file ("" for the main program)
  std::size_t cached_bytes_ = 0;
  // A line that may hold NC language beyond plain words (a cheap test on every line).
  static bool maybe_parametric(const std::string& text);
  // Runs one line's statements and assignments; `out` is the plain block (empty: none).
  void run_line(const std::string& text, std::string& out);
  bool statement(std::string_view keyword, std::string_view line, std::size_t rest);
  void gotos_in_the_main_program(std::size_t at) const;
  void define(std::string_view line, std::size_t at, std::map<std::string, Variable>& into);
  void store(Variable& var, std::size_t offset, const NcValue& value, std::size_t at);
  std::vector<NcValue> values(std::string_view line, std::size_t& i, char close, InterpreterLookup& lookup);
  double counter(const std::string& name);
  void assign_counter(const std::string& name, double value, std::size_t at);
  // Jumps (NC-PARAM-FLOW-1): to a label or block number, forward, backward or both.
  void jump(std::string_view target, bool forward, bool backward, bool must_exist, std::size_t at);
  struct Passed {  // end words of open structures a forward search went past
    int ifs = 0, loops = 0;
  };
  bool find_forward(std::string_view target, Passed* passed = nullptr);
  // By file: targets no line defines, and "TARGET@line": none after that line.
  std::map<std::string, std::set<std::string>> absent_targets_;
  void leave_structures(const Passed& passed);
  void leave_structures_from(int target_line);
  bool find_backward(std::string_view target, int before_line);
  void note_label(const std::string& label, std::streamoff start, int line);
  static bool defines(std::string_view text, std::string_view target);
  // Skips lines to the `end` word matching `open` (nesting counted); with `or_else`, also stops
  // at an ELSE of the same level. Returns the word found.
  std::string skip_block(std::string_view open, std::string_view end, bool or_else);
  void jump_back(const Frame& f);
  void count_backward_jump();
  // NC-PARAM-FLOW-5: REPEAT label [label|ENDLABEL] P=n, REPEATB label P=n; CASE … OF.
  void repeat_section(std::string_view line, std::size_t rest, bool one_block);
  void end_section_pass();
  void case_jump(std::string_view line, std::size_t rest);
  // Where `target` starts (its offset and the lines before it); the reading position is kept.
  std::optional<std::pair<std::streamoff, int>> locate(std::string_view target, bool backward, bool forward);

  Variable* find_variable(const std::string& name);

  // One program level: the main program or a subprogram being run (NC-PARAM-SUB-*).
  struct Context {
    std::unique_ptr<std::istream> owned;  // a subprogram's file, opened when a line is not cached
    std::istream* in = nullptr;
    std::string path;  // a subprogram's file as found
    std::string name;  // the file, for messages ("" for the main program)
    LineCache* cache = nullptr;
    mutable std::streamoff stream_at = -1;        // where `lines` stands in `in` (-1: to be sought)
    LineBuffer lines;                             // `in` read ahead
    std::streamoff offset = 0, start_offset = 0;  // of the next line, of the text's start
    std::streamoff line_start = 0;                // of the line just read
    int line = 0;
    int start_line = 0;          // lines before the text's start (a unit: before its header)
    std::streamoff header = -1;  // its own %_N_…_SPF/MPF header line (NC-PARAM-SUB-8), once seen
    bool begun = false;          // a line other than a comment or header was read
    std::vector<Frame> frames;
    std::vector<int> open_ifs;  // lines of the IF structures whose running branch has not ended
    struct Section {            // a program section being repeated (NC-PARAM-FLOW-5)
      std::streamoff start;
      int start_line;  // lines before its first block
      int last_line;   // its last block's line
      int passes_left;
      std::streamoff resume;  // after the REPEAT block
      int resume_line;
    };
    std::vector<Section> sections;
    std::map<std::string, std::vector<std::pair<std::streamoff, int>>> labels_seen;  // label: (start, lines before)
    std::map<std::string, Variable> variables;                                       // local to this level
    int passes_left = 0;  // P: runs of the subprogram still to come after this one
    std::vector<std::pair<std::string, std::string>> by_reference;  // VAR parameter: (local, caller's)
    std::vector<std::optional<NcValue>> args;                       // the call's arguments (empty: left out)
    std::vector<std::string> arg_names;                             // an argument that is a variable, by name
    bool saved = false;                                             // PROC … SAVE: the state is put back
  };
  static constexpr std::size_t kMaxLevels = 16;  // the main program and 15 subprogram levels
  bool call(std::string_view line, std::size_t word);
  // Where a subprogram's text is: a file of its own, or a unit of the main program's file
  // (NC-PARAM-SUB-8).
  struct SubprogramText {
    std::string file;           // "": a unit of the main program's text
    std::string unit;           // the unit's name as its header writes it (_N_NAME_SPF)
    std::streamoff header = 0;  // where the unit's header line starts
    int line = 0;               // lines before it
  };
  // The subprogram starts: its lines are read next.
  void enter(const SubprogramText& text, std::vector<std::optional<NcValue>> args, std::vector<std::string> names,
             int passes, std::size_t word);
  struct ModalCall {  // MCALL NAME(arguments): after every move of the level it was programmed in
    SubprogramText file;
    std::vector<std::optional<NcValue>> args;
    std::vector<std::string> names;
    std::size_t level;
  };
  std::optional<ModalCall> modal_call_;
  bool modal_call_due_ = false;
  void arguments(std::string_view line, std::size_t& i, std::vector<std::optional<NcValue>>& args,
                 std::vector<std::string>& names);
  void procedure(std::string_view line, std::size_t at);
  void leave_subprogram();
  std::optional<SubprogramText> find_subprogram(const std::string& name) const;
  // NC-PARAM-SUB-8: the units after the first in the main program's text, by name; read once, when
  // a subprogram is first looked for.
  void scan_units() const;
  bool unit_ends(Context& c, std::string_view text) const {
    // A line of the unit's text that begins with neither '%' nor a blank is no header: most lines
    // are answered here, without a call (issue "Performance": every line of a program asks).
    if (c.begun && !text.empty() && text[0] != '%' && text[0] != ' ' && text[0] != '\t') return false;
    return header_ends_unit(c, text);
  }
  bool header_ends_unit(Context& c, std::string_view text) const;
  // The context past `text`, a line just read from its file's line buffer (getline, next_plain).
  void past_line_read(Context& c, std::string_view text) {
    line_padded_ = true;
    c.offset += static_cast<std::streamoff>(text.size()) + 1;
    c.stream_at = c.offset;
    ++c.line;
  }
  mutable std::map<std::string, SubprogramText> units_;
  mutable std::map<std::string, int> duplicate_units_;  // a name's second header: its line
  mutable bool units_scanned_ = false;
  // Units share the main program's stream: a level reading it after another did must seek.
  mutable const std::istream* last_in_ = nullptr;
  mutable std::size_t last_level_ = 0;
  bool reader_knows(const std::string& word);
  // $P_UIFR[n]… (NC-PARAM-SYS-2) or, in_force, $P_IFRAME… (NC-PARAM-SYS-5) from `at` ('[' or '=').
  std::size_t settable_offset(std::string_view line, std::size_t at, bool in_force = false);
  std::map<std::string, bool> known_words_;

  Context& cx() { return stack_.back(); }
  const Context& cx() const { return stack_.back(); }

  SystemValues* system_;
  InterpreterLimits limits_;
  std::uint16_t skip_levels_ = 0;
  bool skipped(const std::string& line);
  std::string raw_;
  // Blocks one line yields beyond its own (a $P_PFRAME assignment: NC-PARAM-FRAME-1), with the
  // line they stand for; handed out before the next line is read.
  std::vector<std::string> pending_;
  std::size_t pending_next_ = 0;
  int pending_line_ = 0;
  // NC-PARAM-FRAME-2: $P_PFRAME[axis, component]=expr from `at` ('['): the programmable frame with
  // that component set, as a frame value; `end` is where the assignment ends.
  NcValue frame_component_assignment(std::string_view line, std::size_t at, std::size_t& end);
  std::vector<Context> stack_;
  std::map<int, double> r_;  // R parameters: global
  std::map<std::string, Variable> globals_;
  std::map<std::string, std::string> macros_;  // NC-PARAM-SUB-7: DEFINE name AS text
  void expand_macros(std::string& line) const;
  std::vector<std::string> source_names_{""};
  std::map<std::string, std::uint32_t> source_ids_;  // NC-PARAM-VAR-3: GUD from definition files
  std::vector<std::string> search_path_;
  std::vector<std::string> machine_cycles_;  // NC-CYCLE-3
  bool subprogram_files_ = true;
  mutable std::map<std::string, std::optional<SubprogramText>> found_;  // subprograms by name
  std::map<std::string, NcValue, std::less<>> machine_values_;          // NC-PARAM-SYS-4
  std::int64_t backward_jumps_ = 0;
  std::size_t total_elements_ = 0;  // of all DEF variables: memory stays bounded
  bool control_flow_ = false;
  std::string statement_block_;  // a block a statement yields (IF … GOTOS: GOTOS)
  friend class InterpreterLookup;
};

}  // namespace cutcom
