// The SINUMERIK words cutcom reads beyond the compensation's own (NC-WORD-*, NC-CYCLE-*), and the
// one wording of every "not supported" and "unknown word" message (NC-ERR-3).
#pragma once

#include <string>
#include <string_view>

namespace cutcom {

enum class NamedWord {
  kActionKeyword,  // SOFT, FFWON, …: kept as an action
  kActionValue,    // ADIS=…, SPOS=…: kept as an action as written
  kActionCall,     // MSG("…"), WORKPIECE(…), …: kept as an action as written
  kDiameter,       // DIAMON, DIAMOF, DIAM90
  kCycle,          // a standard cycle: not simulated
  kModalCall,      // MCALL
  kSubprogramEnd,  // RET
  kNotSimulated,   // SINUMERIK NC that cutcom does not simulate
  kUnknown,        // not a SINUMERIK word cutcom knows
};

NamedWord classify_named_word(std::string_view upper_name);

// NC-CYCLE-1: an E_…/F_… name (ShopMill/ShopTurn) is a cycle only by its prefix: a subprogram of
// the program's own with such a name is called.
bool is_shopmill_cycle_name(std::string_view upper_name);
// NC-PARAM-SUB-1: the subprogram a CALL/PCALL/EXTCALL names (upper case): "PATH/NAME.SPF" is NAME.
std::string called_name(std::string upper_name);
bool is_action_value_wrapper(std::string_view upper_name);  // DC, ACP, ACN, AC, IC
// NC-WORD-9: ID, IDS, WHEN, WHENEVER, FROM, EVERY, DO: a synchronized action to the block's end.
bool starts_synchronized_action(std::string_view upper_name);
// NC-WORD-7: a PLC interface or synchronized-action variable a program writes ($A_OUT, $A_DBB, …).
bool is_machine_output(std::string_view upper_name);
// NC-WORD-7: the workpiece counters a program writes ($AC_ACTUAL_PARTS=…): the machine's, no index.
bool is_machine_counter(std::string_view upper_name);

// "'X' is SINUMERIK NC that cutcom does not simulate (what)".
std::string unsupported_message(std::string_view word, std::string_view what = {});
// "'X' is not a SINUMERIK word cutcom knows (…)".
std::string unknown_message(std::string_view word);

}  // namespace cutcom
