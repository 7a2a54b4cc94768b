// The control's data from the command line's files and options (TOOL-FILE-1/2, NC-OFFSET-2,
// NC-PARAM-VAR-3, NC-PARAM-SUB-1/5, NC-PARAM-SYS-4), each error naming its file or option.
#include "control_data.hpp"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cutcom::cli {

namespace {

template <class Table>
void load_file(Table& table, const std::string& file, const char* what, int channel) {
  if (std::filesystem::is_directory(file)) throw FileError(fmt::format("{} file '{}' is a directory", what, file));
  std::ifstream in(file);
  if (!in) throw FileError(fmt::format("cannot open {} file '{}'", what, file));
  try {
    table.load(in, file, channel);
  } catch (const cutcom::InputError& e) {
    std::string_view detail = e.detail();  // (the table names the file too: once is enough)
    if (detail.starts_with(file + ": ")) detail.remove_prefix(file.size() + 2);
    throw FileError(fmt::format("{}:{}:{}: {}", file, e.line(), e.column(), detail));
  }
}

}  // namespace

void ControlData::into(cutcom::ProgramReader& reader) const {
  reader.set_machine_values(machine_values);
  reader.tools() = tools;
  reader.offsets() = offsets;
  reader.set_limits(limits);
  reader.set_skip_levels(skip_levels);
  reader.set_search_path(search_path);
  reader.set_machine_cycles(machine_cycles);
  for (const auto& [file, text] : definitions) {
    std::istringstream in(text);
    try {
      reader.load_definitions(in);
    } catch (const cutcom::InputError& e) {
      throw FileError(fmt::format("{}:{}:{}: {}", file, e.line(), e.column(), e.detail()));
    }
  }
  if (arguments) {
    try {
      reader.set_arguments(*arguments);
    } catch (const cutcom::InputError& e) {
      throw FileError(fmt::format("--args, column {}: {}", e.column(), e.detail()));
    }
  }
}

cutcom::MachineData machine_data(const RunOptions& o) {
  cutcom::MachineData md;
  for (const auto& f : o.md_files) {
    std::ifstream in(f);
    if (!in) throw cutcom::MachineDataError(fmt::format("cannot open machine data file '{}'", f));
    md.load(in, f, o.channel);
  }
  for (const auto& a : o.md) md.set_assignment(a);
  return md;
}

ControlData control_data(const RunOptions& o) {
  ControlData c;
  for (const auto& f : o.tool_files) load_file(c.tools, f, "tool", o.channel);
  for (const auto& t : o.tool_edges) {
    try {
      c.tools.define(t);  // TOOL-FILE-2: after the archives, so that it overrides them
    } catch (const cutcom::InputError& e) {
      throw FileError(fmt::format("--tool '{}', column {}: {}", t, e.column(), e.detail()));
    }
  }
  if (!o.offsets_file.empty()) load_file(c.offsets, o.offsets_file, "offsets", o.channel);
  c.limits.max_backward_jumps = o.max_loops;
  for (int level : o.skip_levels) c.skip_levels |= static_cast<std::uint16_t>(1u << level);
  for (const auto& f : o.definition_files) {
    if (std::filesystem::is_directory(f)) throw FileError(fmt::format("definitions file '{}' is a directory", f));
    std::ifstream in(f);
    if (!in) throw FileError(fmt::format("cannot open definitions file '{}'", f));
    std::ostringstream text;
    text << in.rdbuf();
    c.definitions.emplace_back(f, text.str());
  }
  c.arguments = o.arguments;
  c.machine_values = machine_data(o).program_values();
  for (const auto& a : o.system_values) {  // NC-PARAM-SYS-4: after the machine data, which they may not replace
    std::pair<std::string, std::string> given;
    try {
      given = cutcom::system_value_assignment(a);
    } catch (const cutcom::MachineDataError& e) {
      throw FileError(fmt::format("--sysvar '{}': {}", a, e.what()));
    }
    if (c.machine_values.count(given.first))
      throw FileError(fmt::format("--sysvar '{}': {} is machine data, given with --md", a, given.first));
    c.machine_values.insert(std::move(given));
  }
  std::filesystem::path folder =
      o.program == "-" ? std::filesystem::path(".") : std::filesystem::path(o.program).parent_path();
  c.search_path.push_back(folder.empty() ? "." : folder.string());
  for (const auto& d : o.search_path) c.search_path.push_back(d);
  for (std::string name : o.machine_cycles) {  // NC-CYCLE-3: names as the control reads them
    for (char& ch : name) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    bool ok = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0]));
    for (char ch : name) ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
    if (!ok)
      throw FileError(fmt::format("--machine-cycle '{}': a subprogram or cycle name (letters, digits, _)", name));
    c.machine_cycles.push_back(name);
  }
  return c;
}

std::string read_all(std::istream& in) {
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace cutcom::cli
