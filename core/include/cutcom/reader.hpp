// Reading SINUMERIK NC text (spec NC-*): one line is one block. The reader turns text into
// BlockWords; the ProgramReader adds modal state, tool data and exact positions (Block).
// Both are streaming: a program of any length is read with bounded memory.
#pragma once

#include <array>
#include <cmath>
#include <deque>
#include <istream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cutcom/block.hpp"
#include "cutcom/block_source.hpp"
#include "cutcom/input_error.hpp"
#include "cutcom/interpreter.hpp"

namespace cutcom {

// Parses the words of one line (NC-LEX-*). Throws InputError. `machine_cycles`: names the
// machine runs as its own cycles or subprograms (NC-CYCLE-3), not simulated as the standard ones.
// `plain_refused`: read_plain_block has already refused this text (Interpreter::plain_refused).
void parse_block_words(std::string_view text, int line, BlockWords& out,
                       const std::vector<std::string>& machine_cycles = {}, bool plain_refused = false);

// Tool data set by $TC_DPn (TOOL-DATA-1).
struct EdgeData {
  Decimal type, position, radius, wear;  // $TC_DP1, $TC_DP2, $TC_DP6, $TC_DP15
  std::array<Decimal, 26> values{};      // every $TC_DPn as assigned (n 1 … 25), for programs that read them
};

// The control's tool table: edges by (T, D) and names by T (TOOL-DATA-1, TOOL-NAME-1).
class ToolTable {
 public:
  void assign(const ToolDataAssignment& a);
  void name(const ToolNameAssignment& a);
  const EdgeData* find(std::int64_t tool, std::int64_t edge) const;
  std::optional<std::int64_t> number_of(const std::string& name) const;
  // The name $TC_TP2[tool] gave tool `tool`, if any (NC-PARAM-SYS-1).
  std::optional<std::string> name_of(std::int64_t tool) const;
  // TOOL-FILE-1: a tool-offset archive (TO_INI.INI convention). Errors name the file and line.
  // `channel`: the channel whose data are read from an archive of several (MD-FILE-1; 0: one only).
  void load(std::istream& in, const std::string& source_name, int channel = 0);
  // TOOL-FILE-2: one edge from the command line, "TOOL[/EDGE]=RADIUS" (TOOL a number or a name).
  // Errors: InputError with line 0 and the column in the text.
  void define(std::string_view spec);

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
  // `channel` as for ToolTable::load.
  void load(std::istream& in, const std::string& source_name, int channel = 0);

 private:
  std::map<int, Point3> offsets_;
};

// The programmable frame (NC-FRAME-2/4): base = offset + shift + R(rotation)·(factor ⊙ p), the
// rotation about one axis (the applicate of the plane it turns), factor = ±scale per axis.
struct ProgrammableFrame {
  std::array<Decimal, 3> factor{Decimal::from_int(1), Decimal::from_int(1), Decimal::from_int(1)};
  std::array<Decimal, 3> shift{};
  Decimal rotation;       // degrees, counter-clockwise seen from the positive rotation axis
  int rotation_axis = 2;  // 0 X, 1 Y, 2 Z
  bool identity() const;
  bool rotated() const { return !rotation.is_zero(); }
};
// Reads blocks one by one and resolves modal state and positions (NC-MODAL-*, NC-POS-*).
class ProgramReader final : public BlockSource, private SystemValues {
 public:
  explicit ProgramReader(std::istream& in, ModalState initial = {});
  // Next block, or false at the end of the text or after M2/M30. Throws InputError.
  // Contour definitions (NC-CONTOUR-*) may hold a block back until the next element is read.
  bool next(Block& out);
  // BlockSource: the next block read into the reader's own (for the engines).
  const Block* next_block() override { return next(current_) ? &current_ : nullptr; }
  // SAR-END-3: after a SAR retraction without end point the tool is where the retraction ended;
  // blocks read after it start there (the engines give the in-plane position exactly).
  void set_position(const Point3& p) override;
  ToolTable& tools() { return tools_; }
  OffsetTable& offsets() {
    offsets_changed_ = true;  // offset_difference_ is taken again at the next block
    return offsets_;
  }
  const std::string& source_name() const { return source_; }
  // NC-PARAM-FLOW-6: the runaway limit of the interpreter layer.
  void set_limits(InterpreterLimits limits) { interpreter_.set_limits(limits); }
  // NC-WORD-2: skip levels switched on (bit n: `/n`); off by default, so skip blocks run.
  void set_skip_levels(std::uint16_t levels) { interpreter_.set_skip_levels(levels); }
  // NC-PARAM-SUB-1: the folders subprograms are looked for in, the program's own first.
  void set_search_path(std::vector<std::string> dirs) { interpreter_.set_search_path(std::move(dirs)); }
  // NC-CYCLE-3: the machine's own cycles and subprograms (upper case): calls of them that no file
  // answers are not simulated, as standard cycles.
  void set_machine_cycles(std::vector<std::string> names) {
    interpreter_.set_machine_cycles(names);
    machine_cycles_ = std::move(names);
  }
  void no_subprogram_files() { interpreter_.no_subprogram_files(); }
  void set_source_name(std::string name) { source_ = std::move(name); }
  // NC-PARAM-SUB-3: where a block of a subprogram stands ("INNER.SPF line 4, called from
  // OUTER.SPF line 7"), by the id its origin carries; "" for 0.
  const std::string& source_text(std::uint32_t id) const { return interpreter_.source_text(id); }
  // NC-PARAM-VAR-3: global user data (GUD) from a definitions file; errors name its lines.
  void load_definitions(std::istream& in) { interpreter_.load_definitions(in); }
  // NC-PARAM-SUB-5: the program is a subprogram run on its own with these arguments.
  void set_arguments(std::string_view list) { interpreter_.set_arguments(list); }
  // NC-PARAM-SYS-4: machine and setting data a program reads by their $ names (MachineData::program_values).
  void set_machine_values(const std::map<std::string, std::string>& values) { interpreter_.set_machine_values(values); }

 private:
  Block current_;  // what next_block() gives
  bool read_block(Block& out);
  bool take_block(Block& out, int line);  // the interpreter's line as a block; false: none
  // NC-PARAM-SYS-1: the system variables a program may read.
  std::optional<double> system_value(std::string_view name, const std::vector<NcValue>& indices) override;
  std::optional<double> g_group_value(double group) const;  // $P_GG[group]
  static bool polar_move(const BlockWords& w);
  // NC-PARAM-SUB-4: PROC … SAVE.
  bool write_settable_offset(const std::string& assignment) override;
  bool write_settable_frame(const std::string& assignment) override;  // NC-PARAM-SYS-5
  std::optional<std::string> programmable_frame() override;           // NC-PARAM-FRAME-1
  std::optional<std::string> programmable_frame_with(int axis, std::string_view component,
                                                     std::string_view value) override;  // NC-PARAM-FRAME-2
  std::optional<std::string> settable_frame(int n) override;                            // NC-PARAM-FRAME-2
  std::optional<std::string> tool_name(double tool) override {                          // NC-PARAM-SYS-1: $TC_TP2[t]
    return tool == std::trunc(tool) && std::abs(tool) < 1e15 ? tools_.name_of(static_cast<std::int64_t>(tool))
                                                             : std::nullopt;
  }
  std::optional<double> frame_component(std::string_view name, const std::vector<NcValue>& indices);
  void save_modal_state() override;
  void restore_modal_state() override;
  struct SavedState {
    ModalState state;
    Units units;
    DiameterMode diameter;
    int offset_index;
    ProgrammableFrame frame;
    std::optional<CircleDefinition> circle_definition;
  };
  std::vector<SavedState> saved_;  // one per open PROC … SAVE
  void resolve(Block& b);
  // The words beyond a plain block's (setting_words.cpp).
  void take_data_words(const BlockWords& w);
  void take_frame_words(Block& b);
  bool take_modal_words(Block& b, ModalState& s);  // true: TRANSMIT switched
  void check_transmit_diameter(const BlockWords& w) const;
  static const char* transformation_name(Transformation t);
  void thread_block(Block& b, int thread);  // NC-WORD-12
  void change_tool(Block& b, ModalState& s);
  void apply_frame(const BlockWords& w, Plane plane);
  Decimal to_base(int axis, const AxisWord& aw, const Decimal& current, bool absolute, bool distance = false) const {
    // The common case (no frame, offset, inch or diameter value in force): the value is the
    // position, as to_base_framed would compute it (every coordinate of every block).
    if (as_written_) return absolute ? aw.value : current + aw.value;
    return to_base_framed(axis, aw, current, absolute, distance);
  }
  Decimal to_base_framed(int axis, const AxisWord& aw, const Decimal& current, bool absolute, bool distance) const;
  Decimal length(const Decimal& v) const;  // the unit of a programmed length
  Decimal frame_value(int axis, const AxisWord& aw, const Decimal& current, bool absolute, bool distance = false) const;
  // to_base is the identity on values: mm, no diameter value, no offset difference, a frame
  // without scale or shift (its rotation is plane_definition's); taken once per block in resolve.
  bool values_as_written() const;
  bool as_written_ = false;
  // The units, diameter mode, frame or offset difference may have changed since as_written_ was
  // taken (select_offset, restore_modal_state): a plain block's words change none of them, so it
  // takes as_written_ anew only then (37 instructions of every block otherwise).
  bool as_written_due_ = true;
  // The translation of the settable offset in force relative to the first one, kept per change.
  const Point3& offset_difference() const { return offset_difference_; }
  void select_offset(int index);
  bool mirrors_plane(Plane plane) const;  // the selected settable offset relative to the first
  void refresh_programmed();              // programmed_ from position_ after a frame or offset change
  void update_programmed(const BlockWords& w, bool absolute_mode);
  void set_pole(const BlockWords& w, Plane plane);
  // NC-POLAR-*, NC-CONTOUR-3..5, NC-FRAME-4: without contour words, CIP/CT or a rotation (every
  // other block) there is nothing to define: that test inline, the definition out of line.
  bool plane_definition(Block& b, ModalState& eff) {
    ang_open_ = false;
    if (!b.words.contour && !circle_definition_ && !frame_.rotated()) return false;
    return define_in_plane(b, eff);
  }
  bool define_in_plane(Block& b, ModalState& eff);
  static void note(Block& b, std::string_view clause, std::string text);

  // NC-CONTOUR-1/2/3/6: the stage that holds a block until the element after it is known.
  bool needs_contour_stage(const Block& b) const;
  void contour_stage(Block& b);
  void finish_pending(Block* next);
  template <typename Stage>
  void out_of_range_is_an_error(int line, Stage&& stage);
  void push_ready(Block&& b);
  void pop_ready(Block& out);  // the first of ready_, which is not empty
  // TOOL-TURN-1: the compensated contour moved to where a turning tool's tip runs; the cutting
  // edge position of an edge (0 unless a turning tool's 1 … 8).
  void tool_tip_offset(Block& b);
  std::int8_t edge_position_of(const EdgeData* e, const ModalState& s, int line) const;
  // "T3 D1", or T="NAME" D1 for a tool the program or the command line named (TOOL-NAME-1): a
  // named tool's number is cutcom's own and means nothing to the programmer.
  std::string tool_and_edge(const ModalState& s) const;

  std::istream& in_;
  Interpreter interpreter_;                  // NC-PARAM-*: variables, expressions and control flow before the words
  std::vector<std::string> machine_cycles_;  // NC-CYCLE-3
  std::string text_;
  int line_ = 0;
  int index_ = 0;
  int end_line_ = 0;             // line of M2/M30, 0 before it
  bool ended_ = false;           // M2/M30 ended a program with control flow: nothing more is read
  bool tip_on_contour_ = false;  // TOOL-TURN-1: the last block ended on the moved contour
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
  int offset_index_ = 0;  // G500
  // NC-PARAM-SYS-5: the frame a program wrote to $P_IFRAME is held as this settable offset; it is
  // in force from the next block; group 8 ($P_UIFRNUM, $P_GG[8]) keeps the G function's number.
  static constexpr int kWrittenFrame = 100;
  bool written_frame_due_ = false;
  int offset_gcode_ = 0;      // the settable offset the G function of group 8 selected
  Point3 offset_difference_;  // of offset_index_ (select_offset)
  bool offsets_changed_ = false;
  int first_offset_ = -1;
  Point3 first_translation_;  // its translation when it was first selected                              // the settable
                              // offset whose workpiece system the output uses
  ProgrammableFrame frame_;   // programmable frame
  Point3 programmed_;         // the position in the frame's system (NC-FRAME-4, NC-POLAR-1)
  bool programmed_known_ = true;                       // else recomputed from position_ when a block needs it
  std::array<Decimal, 2> pole_{};                      // NC-POLAR-1: in the frame's system, plane abscissa/ordinate
  Decimal polar_angle_, polar_radius_;                 // NC-POLAR-2: the last AP and RP
  std::optional<CircleDefinition> circle_definition_;  // CIP/CT in force (motion group)
  int thread_ = 0;                                     // NC-WORD-12: G33 G34 G35 G331 G332 in force, else 0
  // MD-20150-2: no block has programmed the plane yet, and the lathe hint was not given.
  bool plane_programmed_ = false;
  bool lathe_hint_given_ = false;
  std::string initial_plane_hint() const;
  Decimal rounding_modal_;        // RNDM (0: off)
  Decimal corner_feed_modal_;     // FRCM (0: off)
  std::optional<Block> pending_;  // NC-CONTOUR-*: held until the next element
  bool pending_ang_ = false;
  Decimal pending_radius_;  // RND/RNDM radius and FRCM feed in force when pending_ was read
  Decimal pending_feed_;
  bool ang_open_ = false;            // the block just resolved opens a two-block ANG definition
  Block last_element_;               // geometry of the last block that moved in the plane (CT)
  bool last_element_valid_ = false;  // pending_ is the first block of a two-block ANG definition
  std::vector<Block> between_;       // up to three blocks without plane motion after pending_
  std::deque<Block> ready_;          // resolved blocks waiting to be handed out
  std::array<bool, 3> unknown_{};    // NC-CYCLE-1: axes whose position a cycle left unknown
  std::string unknown_after_;        // what left them unknown
  int unknown_line_ = 0;
  bool modal_call_ = false;
  std::string modal_cycle_;
};

}  // namespace cutcom
