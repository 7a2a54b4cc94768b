// Machine data (spec MD-*): named settings with defaults and validation, settable as
// `--md MD20204=0.02` (or by the $MC_ name) on the command line and from a file.
#pragma once

#include <istream>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cutcom/block.hpp"
#include "cutcom/decimal.hpp"

namespace cutcom {

class MachineDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MachineData {
  // Upper limits of the block counts: they size fast's fixed look-ahead buffer.
  static constexpr int kMaxCheckBlocks = 50;
  static constexpr int kMaxDummyBlocks = 50;

  int wab_maxnum_dummy_blocks = 5;                                    // MD20202
  Decimal wab_clearance_tolerance = Decimal::from_units(10'000'000);  // MD20204, 0.01 mm
  Decimal cutcom_corner_limit = Decimal::from_int(100);               // MD20210, degrees
  Decimal cutcom_max_disc = Decimal::from_int(50);                    // MD20220
  Decimal cutcom_curve_insert_limit = Decimal::from_int(10);          // MD20230, degrees
  int cutcom_maxnum_check_blocks = 3;                                 // MD20240
  int cutcom_maxnum_dummy_blocks = 5;                                 // MD20250
  EdgeStrategy group48_reset = EdgeStrategy::kG462;                   // MD20150 $MC_GCODE_RESET_VALUES[47]
  Plane group6_reset = Plane::kG17;                                   // MD20150 $MC_GCODE_RESET_VALUES[5]
  int cutting_edge_default = 1;                                       // MD20270
  int sum_offset_default = 0;                                         // MD20272
  int tool_change_mode = 0;                                           // MD22550
  Decimal circle_error_const = Decimal::from_units(10'000'000);       // MD21000, 0.01 mm
  Decimal circle_error_factor = Decimal::from_units(1'000'000);       // MD21010, 0.001

  // NC-PARAM-SYS-4: any other machine or setting datum a program reads ($MN_…, $MC_…, $MA_…,
  // $SN_…, $SC_…, $SA_…, with its index: "$MN_AXCONF_MACHAX_NAME_TAB[0]"), as its value's text (a
  // decimal number or a "quoted" string). cutcom models nothing by them.
  std::map<std::string, std::string> readable;

  // Sets one datum from NAME=VALUE text; NAME is "MD20204" or "$MC_WAB_CLEARANCE_TOLERANCE".
  void set(std::string_view name, std::string_view value);
  void set_assignment(std::string_view name_equals_value);
  // MD-FILE-1: reads NAME=VALUE lines; '#' or ';' start a comment; the control's archive framing
  // is passed over. `channel`: whose data an archive of several channels gives (0: one only).
  // Errors name the file and line.
  void load(std::istream& in, const std::string& source_name, int channel = 0);
  // The modal state at program start that machine data decide (group 48 initial setting).
  ModalState initial_state() const;
  // NC-PARAM-SYS-4: what a program reads by the data's $ names: the modelled data (by their
  // names in the catalogue) and `readable`.
  std::map<std::string, std::string> program_values() const;
};

// Descriptions for documentation and `cutcom md`.
struct MachineDatumInfo {
  std::string_view id;    // "MD20204"
  std::string_view name;  // "$MC_WAB_CLEARANCE_TOLERANCE"
  std::string_view unit;
  std::string_view range;
  std::string_view meaning;
  std::string_view clause;  // spec clause defining the default
};
const std::vector<MachineDatumInfo>& machine_data_catalogue();
std::string machine_datum_value(const MachineData& md, std::string_view id);
// NC-PARAM-SYS-4: $MN_ $MC_ $MA_ $SN_ $SC_ $SA_ (upper case): machine or setting data.
bool is_machine_or_setting_datum(std::string_view upper_name);
// NC-PARAM-SYS-4: "$A_IN[1]=1" (any system variable a program reads that cutcom does not model)
// as its name, upper case with its index, and its value's text. Throws MachineDataError.
std::pair<std::string, std::string> system_value_assignment(std::string_view text);

}  // namespace cutcom
