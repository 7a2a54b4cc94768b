// NC-WORD-*, NC-CYCLE-*, NC-ERR-3: which multi-letter words are actions, cycles, or known
// SINUMERIK NC outside cutcom's scope. The lists are the programming manual's words that real
// part programs carry around their contours; anything else is named as unknown.
#include "nc_vocabulary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace cutcom {

namespace {

constexpr std::string_view kActionKeywords[] = {
    "SOFT", "BRISK", "DRIVE", "FFWON", "FFWOF", "CFC", "CFTCP", "CFIN", "COMPON", "COMPCAD", "COMPCURV", "COMPSURF",
    "COMPOF", "UPATH", "SPATH", "CUT2D", "SOFTA", "BRISKA", "DRIVEA",
    // NC-WORD-7: single block and display suppression, path and feed modes, orientation and tool
    // offset references, rotations off, spindle position control: nothing of the 2D path.
    "SBLOF", "SBLON", "DISPLOF", "DISPLON", "CP", "PTP", "PTPG0", "FNORM", "ORIWKS", "ORIMKS", "TOWSTD", "PAROTOF",
    "TOROTOF", "SPCON", "SPCOF",
    // NC-WORD-7: the preprocessing buffer's control
    "FIFOCTRL", "STOPFIFO", "STARTFIFO",
    // NC-WORD-7: feed profiles, corner deceleration off, contour precision, orientation
    // interpolation, fast retraction for threads, handwheel offsets off
    "FLIN", "FCUB", "FENDNORM", "CPRECON", "CPRECOF", "ORIAXES", "ORIVECT", "ORIEULER", "ORIRPY", "LFON", "LFOF",
    "DRFOF",
    // NC-WORD-10: tool length offsets: the tool tip stays on the programmed path
    "TOFFOF",
    // NC-WORD-7: the working area limitation on and off, its groups in the workpiece system
    "WALIMON", "WALIMOF", "WALCS0", "WALCS1", "WALCS2", "WALCS3", "WALCS4", "WALCS5", "WALCS6", "WALCS7", "WALCS8",
    "WALCS9", "WALCS10",
    // NC-WORD-7: grinding: constant wheel peripheral speed, tool monitoring (with their tools)
    "GWPSON", "GWPSOF", "TMON", "TMOF",
    // NC-WORD-7: diameter programming in cycles off, orientation at outer corners, the boundary
    // conditions of splines (which are not simulated)
    "DIAMCYCOF", "ORIC", "ORID", "BAUTO", "BNAT", "BTAN", "EAUTO", "ENAT", "ETAN",
    // NC-WORD-7: orientation smoothing, the preprocessing stop's suppression, repositioning
    // modes, handwheel and overlay offsets off, clearance control off, feed per revolution of
    // positioning axes off; the exact stop of positioning axes (FINEA[C], FINEA=C)
    "ORISON", "ORISOF", "STOPREOF", "RMB", "RME", "RMI", "RMN", "CORROF", "CLGOF", "FPRAOF", "FINEA", "COARSEA",
    "IPOENDA"};
constexpr std::string_view kActionValues[] = {"ADIS", "ADISPOS", "LIMS", "SPOS", "SPOSA",
                                              // NC-WORD-7: compressor tolerances, axis dynamics
                                              "CTOL", "OTOL", "ATOL", "ACC", "VELOLIM", "JERKLIM",
                                              // NC-WORD-8: rotary axes as positioning axes, their feed
                                              "POS", "POSA", "FA",
                                              // NC-CYCLE-1: the fixed point of G75
                                              "FP",
                                              // NC-WORD-7: programmable override, rotary feed radius
                                              "OVR", "FGREF",
                                              // NC-WORD-10: tool length offsets, programmed
                                              "TOFFL", "TOFF",
                                              // NC-WORD-12: thread start angle, run-in and run-out
                                              "SF", "DITS", "DITE",
                                              // NC-WORD-7: an axis's speed limit, the repositioning
                                              // path, the retraction position of extended stop and retract
                                              "FL", "DISPR", "POLF"};
constexpr std::string_view kActionCalls[] = {
    "MSG", "WORKPIECE", "GROUP_BEGIN", "GROUP_END", "CYCLE832", "SETMS",
    // NC-WORD-8: the rotary axes set to an orientation
    "ORIRESET",
    // NC-WORD-9: synchronized actions cancelled, locked, unlocked
    "CANCEL", "LOCK", "UNLOCK",
    // NC-WORD-7: channel coordination, piece count, feed group
    "WAITM", "WAITMC", "WAITE", "WAITS", "SETM", "CLEARM", "SETPIECE", "FGROUP",
    // NC-WORD-7: waiting for positioning axes
    "WAITP",
    // NC-WORD-10: tool length offsets, programmed
    "TOFFON",
    // NC-WORD-7: tangential follow-up of a rotary axis, a
    // file written, the subprograms' search path
    "TANG", "TANGON", "TANGOF", "WRITE", "CALLPATH",
    // NC-WORD-7: a file written and closed, feed per revolution
    // from an axis, motion end of positioning axes, clearance
    // control, the retraction axes of extended stop and retract
    "WRTPR", "EXTCLOSE", "FPR", "FPRAON", "IPOBRKA", "ADISPOSA", "CLGON", "POLFMASK", "POLFMLIN"};

// Known SINUMERIK words cutcom does not simulate, and why (the message names the family).
struct Unsupported {
  std::string_view word, family;
};
constexpr Unsupported kUnsupported[] = {
    {"DEF", "variables (issue: parametric programs)"},
    {"IF", "control flow"},
    {"ELSE", "control flow"},
    {"ENDIF", "control flow"},
    {"GOTO", "control flow"},
    {"GOTOF", "control flow"},
    {"GOTOB", "control flow"},
    {"GOTOC", "control flow"},
    {"WHILE", "control flow"},
    {"ENDWHILE", "control flow"},
    {"FOR", "control flow"},
    {"ENDFOR", "control flow"},
    {"LOOP", "control flow"},
    {"ENDLOOP", "control flow"},
    {"REPEAT", "control flow"},
    {"REPEATB", "control flow"},
    {"UNTIL", "control flow"},
    {"CASE", "control flow"},
    {"PROC", "subprograms"},
    {"CALL", "subprogram calls"},
    {"PCALL", "subprogram calls"},
    {"EXTCALL", "subprogram calls"},
    {"SAVE", "subprograms"},
    {"CUTCONON", "keeping the compensation constant (CUTCONON)"},
    {"CUTCONOF", "keeping the compensation constant (CUTCONOF)"},
    {"ASPLINE", "splines"},
    {"BSPLINE", "splines"},
    {"CSPLINE", "splines"},
    {"POLY", "polynomials"},
    {"TRACYL", "transformations"},
    {"TRAANG", "transformations: the inclined axis"},
    {"TRACON", "transformations: chained"},
    {"CUT2DF", "compensation in a frame plane"},
    {"CUT3DC", "3D compensation"},
    {"CUT3DF", "3D compensation"},
    {"CUT3DFF", "3D compensation"},
    {"CUT3DFS", "3D compensation"},
    {"CUT3DCC", "3D compensation"},
    {"TOFFR", "a programmed tool radius offset"},
    {"G291", "the ISO dialect; G290, the SINUMERIK dialect, is read"},
    {"PRESETON", "setting the actual value"},
    {"CROT", "frame functions"},
    {"PAROT", "frame functions: the workpiece's rotation"},
    {"TOROT", "frame functions: the tool's orientation"},
    {"TOFRAME", "frame functions: the tool's orientation"},
    {"ROTS", "frame functions: solid angles"},
    {"AROTS", "frame functions: solid angles"},
    {"TCARR", "orientable tool holders"},
    {"TCOABS", "orientable tool holders"},
    {"TCOFR", "orientable tool holders"},
    // Named so a program stops with the family, not as an unknown word (NC-ERR-3).
    {"SETINT", "interrupt routines"},
    {"ENABLE", "interrupt routines"},
    {"DISABLE", "interrupt routines"},
    {"CLRINT", "interrupt routines"},
    {"TRAILON", "coupled motion"},
    {"TRAILOF", "coupled motion"},
    {"COUPON", "coupled motion"},
    {"COUPOF", "coupled motion"},
    {"FXS", "travel to fixed stop"},
    {"FXST", "travel to fixed stop"},
    {"FXSW", "travel to fixed stop"},
    {"GEOAX", "geometry axes switched over"},
    {"TCA", "tool management: a tool change of its own"},
    {"PUTFTOC", "tool management: a fine tool offset written"},
    {"DELDL", "tool management: sum offsets deleted"},
    {"GETSELT", "tool management"},
    {"CHKDNO", "tool management"},
    {"REPOSA", "repositioning at the end of an interrupt routine"},
    {"REPOSL", "repositioning at the end of an interrupt routine"},
    {"REPOSQ", "repositioning at the end of an interrupt routine"},
    {"REPOSQA", "repositioning at the end of an interrupt routine"},
    {"REPOSH", "repositioning at the end of an interrupt routine"},
    {"REPOSHA", "repositioning at the end of an interrupt routine"},
    {"MEAS", "measuring"},
    {"MEAW", "measuring"},
    {"MEASA", "measuring"},
    {"MEAWA", "measuring"},
    {"DELDTG", "delete distance-to-go"},
};

template <std::size_t N>
bool contains(const std::string_view (&list)[N], std::string_view n) {
  return std::find(std::begin(list), std::end(list), n) != std::end(list);
}

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

bool is_shopmill_cycle_name(std::string_view n) {
  return (n.substr(0, 2) == "E_" || n.substr(0, 2) == "F_") && n.size() > 2;
}

std::string called_name(std::string n) {
  std::size_t slash = n.find_last_of("/\\");
  if (slash != std::string::npos) n = n.substr(slash + 1);  // EXTCALL "PATH/NAME": the name
  for (const char* ext : {".SPF", ".MPF"})
    if (n.size() > 4 && n.compare(n.size() - 4, 4, ext) == 0) n.resize(n.size() - 4);
  return n;
}

bool starts_synchronized_action(std::string_view n) {
  return n == "WHEN" || n == "WHENEVER" || n == "EVERY" || n == "FROM" || n == "DO" || n == "ID" || n == "IDS";
}

NamedWord classify_named_word(std::string_view n) {
  if (contains(kActionKeywords, n)) return NamedWord::kActionKeyword;
  if (contains(kActionValues, n)) return NamedWord::kActionValue;
  if (contains(kActionCalls, n)) return NamedWord::kActionCall;
  if (n == "DIAMON" || n == "DIAMOF" || n == "DIAM90") return NamedWord::kDiameter;
  if (n == "MCALL") return NamedWord::kModalCall;
  if (n == "RET") return NamedWord::kSubprogramEnd;
  // NC-CYCLE-1: CYCLEnn, POCKETn, SLOTn, LONGHOLE, HOLESn, ShopMill/ShopTurn E_…/F_… and SUPA.
  if (n == "SUPA" || n == "LONGHOLE") return NamedWord::kCycle;
  for (std::string_view p :
       {std::string_view("CYCLE"), std::string_view("POCKET"), std::string_view("SLOT"), std::string_view("HOLES")})
    if (n.substr(0, p.size()) == p && all_digits(n.substr(p.size()))) return NamedWord::kCycle;
  if (is_shopmill_cycle_name(n)) return NamedWord::kCycle;
  for (const Unsupported& u : kUnsupported)
    if (u.word == n) return NamedWord::kNotSimulated;
  return NamedWord::kUnknown;
}

bool is_machine_output(std::string_view n) {
  static constexpr std::string_view kOutputs[] = {"$A_OUT", "$A_OUTA", "$A_DBB",     "$A_DBW",
                                                  "$A_DBD", "$A_DBR",  "$AC_MARKER", "$AC_PARAM"};
  return contains(kOutputs, n);
}

bool is_machine_counter(std::string_view n) {
  static constexpr std::string_view kCounters[] = {"$AC_ACTUAL_PARTS", "$AC_TOTAL_PARTS", "$AC_REQUIRED_PARTS",
                                                   "$AC_SPECIAL_PARTS"};
  return contains(kCounters, n);
}

bool is_action_value_wrapper(std::string_view n) {
  return n == "DC" || n == "ACP" || n == "ACN" || n == "AC" || n == "IC";
}

std::string unsupported_message(std::string_view word, std::string_view what) {
  std::string family(what);
  if (family.empty())
    for (const Unsupported& u : kUnsupported)
      if (u.word == word) family = u.family;
  if (family.empty()) return fmt::format("'{}' is SINUMERIK NC that cutcom does not simulate", word);
  return fmt::format("'{}' is SINUMERIK NC that cutcom does not simulate ({})", word, family);
}

std::string unknown_message(std::string_view word) {
  return fmt::format(
      "'{}' is not a SINUMERIK word cutcom knows (a variable must be defined with DEF first; a subprogram "
      "is looked for as NAME.SPF in the program's folder and --search-path; a cycle of the machine itself, not "
      "simulated: --machine-cycle {})",
      word, word);
}

}  // namespace cutcom
