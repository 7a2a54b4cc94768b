// The command line's shared parts: the options of `cutcom run`, the control's data they name
// (machine data, tool table, offsets, GUD, subprogram folders) and the exit statuses.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cutcom/machine_data.hpp"
#include "cutcom/reader.hpp"

namespace cutcom::cli {

constexpr int kDone = 0, kAlarm = 1, kBadInput = 2;

struct RunOptions {
  std::string program;
  std::string engine = "fast";
  std::string format = "text";
  std::string output;
  std::vector<std::string> md;
  std::vector<std::string> md_files;
  std::vector<std::string> system_values;  // NC-PARAM-SYS-4: --sysvar
  std::vector<std::string> tool_files;
  std::string offsets_file;
  bool trace = false;
  bool stage_times = false;  // --stage-times: each thread's processor time on standard error
  std::int64_t max_loops = cutcom::InterpreterLimits{}.max_backward_jumps;
  std::vector<std::string> search_path;
  std::vector<std::string> tool_edges;  // TOOL-FILE-2
  std::vector<std::string> definition_files;
  std::optional<std::string> arguments;
  std::vector<int> skip_levels;             // NC-WORD-2: --skip
  std::vector<std::string> machine_cycles;  // NC-CYCLE-3: --machine-cycle
  int channel = 0;                          // MD-FILE-1: --channel, whose data the archives give (0: one only)
};

// A data file given on the command line is wrong: names the file and line (exit 2).
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// TOOL-FILE-1, NC-OFFSET-2: the control's tool table and settable offsets from files.
struct ControlData {
  cutcom::ToolTable tools;
  cutcom::OffsetTable offsets;
  cutcom::InterpreterLimits limits;
  std::vector<std::string> search_path;  // NC-PARAM-SUB-1: the program's folder, then --search-path
  std::vector<std::pair<std::string, std::string>> definitions;  // NC-PARAM-VAR-3: (file, text)
  std::optional<std::string> arguments;                          // NC-PARAM-SUB-5
  std::map<std::string, std::string> machine_values;             // NC-PARAM-SYS-4
  std::uint16_t skip_levels = 0;                                 // NC-WORD-2: bit n, level /n on
  std::vector<std::string> machine_cycles;                       // NC-CYCLE-3, upper case
  void into(cutcom::ProgramReader& reader) const;                // the reader set up as `cutcom run` sets it up
};

cutcom::MachineData machine_data(const RunOptions& o);  // --md-file, then --md
ControlData control_data(const RunOptions& o);          // everything `cutcom run` gives the reader
std::string read_all(std::istream& in);

}  // namespace cutcom::cli
