#include "cutcom/machine_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "archive_file.hpp"

namespace cutcom {

const std::vector<MachineDatumInfo>& machine_data_catalogue() {
  static const std::vector<MachineDatumInfo> k = {
      {"MD20150[47]", "$MC_GCODE_RESET_VALUES[47]", "", "1 (G460), 2 (G461), 3 (G462)",
       "initial setting of G group 48 (approach/retraction behaviour)", "MD-20150-1"},
      {"MD20150[5]", "$MC_GCODE_RESET_VALUES[5]", "", "1 (G17), 2 (G18), 3 (G19)",
       "initial setting of G group 6 (working plane; lathes start in G18)", "MD-20150-2"},
      {"MD20202", "$MC_WAB_MAXNUM_DUMMY_BLOCKS", "blocks", "0 .. 50",
       "blocks without traversing motion between a SAR block and the direction-defining block", "MD-20202-1"},
      {"MD20204", "$MC_WAB_CLEARANCE_TOLERANCE", "mm", ">= 0", "tolerance of the SAR direction-reversal check",
       "MD-20204-1"},
      {"MD20210", "$MC_CUTCOM_CORNER_LIMIT", "degrees", "0 .. 180", "contour angle above which G451 switches to G450",
       "MD-20210-1"},
      {"MD20220", "$MC_CUTCOM_MAX_DISC", "", "0 .. 100", "largest DISC value", "MD-20220-1"},
      {"MD20230", "$MC_CUTCOM_CURVE_INSERT_LIMIT", "degrees", "0 .. 180",
       "contour angle below which G450 switches to G451", "MD-20230-1"},
      {"MD20240", "$MC_CUTCOM_MAXNUM_CHECK_BLOCKS", "blocks", "1 .. 50",
       "blocks examined by predictive contour calculation and collision detection", "MD-20240-1"},
      {"MD20250", "$MC_CUTCOM_MAXNUM_DUMMY_BLOCKS", "blocks", "0 .. 50",
       "blocks without motion in the compensation plane between two compensated blocks", "MD-20250-1"},
      {"MD20270", "$MC_CUTTING_EDGE_DEFAULT", "", "-1 .. 32000",
       "edge active after a tool change: > 0 that edge, 0 none (D0), -1 the D number stays", "TOOL-CHANGE-2"},
      {"MD20272", "$MC_SUMCORR_DEFAULT", "", "0 .. 6",
       "sum offset (DL) active when an edge becomes active: 0 none, n DL=n", "TOOL-SUM-1"},
      {"MD22550", "$MC_TOOL_CHANGE_MODE", "", "0, 1", "0: T changes the tool; 1: T preselects, M6 changes",
       "TOOL-CHANGE-1"},
      {"MD21000", "$MC_CIRCLE_ERROR_CONST", "mm", ">= 0",
       "end point of a circle may miss the circle by this much (or MD21010 x radius)", "MD-21000-1"},
      {"MD21010", "$MC_CIRCLE_ERROR_FACTOR", "", ">= 0", "circle end point tolerance per mm of radius", "MD-21010-1"},
  };
  return k;
}

namespace {

using archive::trim;
using archive::upper;

const MachineDatumInfo& lookup(std::string_view name) {
  std::string u = upper(trim(name));
  for (const auto& d : machine_data_catalogue())
    if (u == d.id || u == d.name) return d;
  throw MachineDataError(
      fmt::format("unknown machine datum '{}' (known: MD20150[5], MD20150[47], MD20202, MD20204, MD20210, "
                  "MD20220, MD20230, MD20240, MD20250, MD20270, MD20272, MD22550, MD21000, MD21010; "
                  "a datum a program reads is given by its $ name: $MN_…, $MC_…, $MA_…, $SN_…, $SC_…, $SA_…)",
                  name));
}

Decimal decimal_in(const MachineDatumInfo& d, std::string_view text, Decimal lo, std::optional<Decimal> hi) {
  auto r = Decimal::parse(trim(text));
  if (!r.value && r.error == Decimal::ParseError::kOutOfRange)
    throw MachineDataError(fmt::format("{} = {} is out of range ({})", d.id, trim(text), d.range));
  if (!r.value && r.error == Decimal::ParseError::kTooManyDecimals)
    throw MachineDataError(fmt::format("{}: '{}' has more than nine decimals", d.id, text));
  if (!r.value) throw MachineDataError(fmt::format("{}: '{}' is not a decimal number", d.id, text));
  if (*r.value < lo || (hi && *r.value > *hi))
    throw MachineDataError(fmt::format("{} = {} is out of range ({})", d.id, r.value->to_string(), d.range));
  return *r.value;
}

int count_in(const MachineDatumInfo& d, std::string_view text, int lo, int hi) {
  Decimal v = decimal_in(d, text, Decimal::from_int(lo), Decimal::from_int(hi));
  auto i = v.to_integer();
  if (!i) throw MachineDataError(fmt::format("{} must be a whole number, not {}", d.id, v.to_string()));
  return static_cast<int>(*i);
}

}  // namespace

namespace {

// NC-PARAM-SYS-4: a system variable's name, '$' and letters, digits and '_', with an optional index
// [i] or [i,j] (upper case, without spaces).
bool is_system_variable_name(std::string_view u) {
  if (u.size() < 2 || u[0] != '$') return false;
  std::size_t k = 1;
  while (k < u.size() && (std::isalnum(static_cast<unsigned char>(u[k])) || u[k] == '_')) ++k;
  if (k == 1) return false;
  if (k == u.size()) return true;
  if (u[k] != '[' || u.back() != ']' || u.size() - k < 3) return false;
  for (char c : u.substr(k + 1, u.size() - k - 2))
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != ',') return false;
  return true;
}

// NC-PARAM-SYS-4: $MN_ $MC_ $MA_ $SN_ $SC_ $SA_ (machine data of the NC, channel, axis; setting
// data likewise), with a name and an optional index.
bool is_readable_datum_name(std::string_view u) {
  return is_machine_or_setting_datum(u) && u[4] != '[' && is_system_variable_name(u);
}

// A system variable's name as a key: upper case, without spaces ("$mc_x[ 1 ]" is "$MC_X[1]").
std::string variable_key(std::string_view name) {
  std::string u;
  for (char c : upper(trim(name)))
    if (c != ' ' && c != '\t') u += c;
  return u;
}

// The value's text of a given system variable: a decimal number or a "quoted" text.
std::string variable_value(const std::string& key, std::string_view value) {
  std::string_view v = trim(value);
  bool quoted = v.size() >= 2 && v.front() == '"' && v.back() == '"' &&
                v.substr(1, v.size() - 2).find('"') == std::string_view::npos;
  if (!quoted && !Decimal::parse(v).value)
    throw MachineDataError(fmt::format("{}: '{}' is neither a decimal number nor a \"quoted\" text", key, v));
  return std::string(v);
}

// MD-FILE-1: a hexadecimal 'H…' or binary 'B…' constant, as the control archives bit masks, as
// its decimal text; any other value as it is.
std::string numeric_text(std::string_view value) {
  std::string_view v = trim(value);
  if (v.size() < 4 || v.front() != '\'' || v.back() != '\'') return std::string(value);
  char base = static_cast<char>(std::toupper(static_cast<unsigned char>(v[1])));
  std::string_view digits = v.substr(2, v.size() - 3);
  if ((base != 'H' && base != 'B') || digits.size() > (base == 'H' ? 15u : 60u)) return std::string(value);
  std::int64_t n = 0;
  for (char c : digits) {
    int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0'
            : base == 'H' && std::isxdigit(static_cast<unsigned char>(c))
                ? std::toupper(static_cast<unsigned char>(c)) - 'A' + 10
                : 99;
    if (d >= (base == 'H' ? 16 : 2))
      throw MachineDataError(fmt::format("{} is not a {} constant", v, base == 'H' ? "hexadecimal" : "binary"));
    n = n * (base == 'H' ? 16 : 2) + d;
  }
  return std::to_string(n);
}
}  // namespace

void MachineData::set(std::string_view name, std::string_view raw_value) {
  const std::string value_text = numeric_text(raw_value);
  const std::string_view value = value_text;
  std::string u = variable_key(name);
  bool catalogued = std::any_of(machine_data_catalogue().begin(), machine_data_catalogue().end(),
                                [&](const MachineDatumInfo& d) { return u == d.id || u == d.name; });
  if (!catalogued && is_readable_datum_name(u)) {  // NC-PARAM-SYS-4: a value programs read
    readable[u] = variable_value(u, value);
    return;
  }
  const MachineDatumInfo& d = lookup(name);
  std::string_view id = d.id;
  if (id == "MD20150[47]") {
    int v = count_in(d, value, 1, 3);
    group48_reset = v == 1 ? EdgeStrategy::kG460 : v == 2 ? EdgeStrategy::kG461 : EdgeStrategy::kG462;
  } else if (id == "MD20150[5]") {
    int v = count_in(d, value, 1, 3);
    group6_reset = v == 1 ? Plane::kG17 : v == 2 ? Plane::kG18 : Plane::kG19;
  } else if (id == "MD20202") {
    wab_maxnum_dummy_blocks = count_in(d, value, 0, kMaxDummyBlocks);
  } else if (id == "MD20204") {
    wab_clearance_tolerance = decimal_in(d, value, Decimal{}, std::nullopt);
  } else if (id == "MD20210") {
    cutcom_corner_limit = decimal_in(d, value, Decimal{}, Decimal::from_int(180));
  } else if (id == "MD20220") {
    cutcom_max_disc = decimal_in(d, value, Decimal{}, Decimal::from_int(100));
  } else if (id == "MD20230") {
    cutcom_curve_insert_limit = decimal_in(d, value, Decimal{}, Decimal::from_int(180));
  } else if (id == "MD20240") {
    cutcom_maxnum_check_blocks = count_in(d, value, 1, kMaxCheckBlocks);
  } else if (id == "MD20250") {
    cutcom_maxnum_dummy_blocks = count_in(d, value, 0, kMaxDummyBlocks);
  } else if (id == "MD20270") {
    cutting_edge_default = count_in(d, value, -1, 32000);
  } else if (id == "MD20272") {
    sum_offset_default = count_in(d, value, 0, 6);
  } else if (id == "MD22550") {
    tool_change_mode = count_in(d, value, 0, 1);
  } else if (id == "MD21000") {
    circle_error_const = decimal_in(d, value, Decimal{}, std::nullopt);
  } else if (id == "MD21010") {
    circle_error_factor = decimal_in(d, value, Decimal{}, std::nullopt);
  }
}

void MachineData::set_assignment(std::string_view text) {
  auto eq = text.find('=');
  if (eq == std::string_view::npos)
    throw MachineDataError(fmt::format("'{}': expected NAME=VALUE, e.g. MD20204=0.02", text));
  set(text.substr(0, eq), text.substr(eq + 1));
}

// MD-FILE-1: NAME=VALUE lines, also in the framing of the control's archive (a header, CHANDATA,
// M17, comments).
void MachineData::load(std::istream& in, const std::string& source_name, int channel) {
  auto fail = [&](int n, const std::string& what) -> void {
    throw MachineDataError(fmt::format("{}:{}: {}", source_name, n, what));
  };
  archive::read_lines(
      in,
      [&](int n, const std::string& line, const std::string&) {
        std::string_view s = line;
        auto c = s.find_first_of("#;");
        if (c != std::string_view::npos) s = s.substr(0, c);
        s = trim(s);
        if (s.empty()) return;
        try {
          set_assignment(s);
        } catch (const MachineDataError& e) {
          fail(n, e.what());
        }
      },
      fail, channel);
}

ModalState MachineData::initial_state() const {
  ModalState s;
  s.edge_strategy = group48_reset;
  s.plane = group6_reset;
  s.md_edge_default = cutting_edge_default;
  s.md_sum_offset_default = sum_offset_default;
  s.md_change_on_m6 = tool_change_mode == 1;
  return s;
}

bool is_machine_or_setting_datum(std::string_view n) {
  return n.size() > 4 && n[0] == '$' && (n[1] == 'M' || n[1] == 'S') && (n[2] == 'N' || n[2] == 'C' || n[2] == 'A') &&
         n[3] == '_';
}

std::pair<std::string, std::string> system_value_assignment(std::string_view text) {
  auto eq = text.find('=');
  if (eq == std::string_view::npos)
    throw MachineDataError(fmt::format("'{}': expected $NAME=VALUE, e.g. $A_IN[1]=1", text));
  std::string u = variable_key(text.substr(0, eq));
  if (!is_system_variable_name(u))
    throw MachineDataError(
        fmt::format("'{}' is not a system variable's name ($NAME or $NAME[index])", text.substr(0, eq)));
  return {u, variable_value(u, text.substr(eq + 1))};
}

std::map<std::string, std::string> MachineData::program_values() const {
  std::map<std::string, std::string> v = readable;
  for (const auto& d : machine_data_catalogue()) v[std::string(d.name)] = machine_datum_value(*this, d.id);
  return v;
}

std::string machine_datum_value(const MachineData& md, std::string_view id) {
  if (id == "MD20150[47]")
    return md.group48_reset == EdgeStrategy::kG460 ? "1" : md.group48_reset == EdgeStrategy::kG461 ? "2" : "3";
  if (id == "MD20150[5]") return md.group6_reset == Plane::kG17 ? "1" : md.group6_reset == Plane::kG18 ? "2" : "3";
  if (id == "MD20202") return std::to_string(md.wab_maxnum_dummy_blocks);
  if (id == "MD20204") return md.wab_clearance_tolerance.to_string();
  if (id == "MD20210") return md.cutcom_corner_limit.to_string();
  if (id == "MD20220") return md.cutcom_max_disc.to_string();
  if (id == "MD20230") return md.cutcom_curve_insert_limit.to_string();
  if (id == "MD20240") return std::to_string(md.cutcom_maxnum_check_blocks);
  if (id == "MD20250") return std::to_string(md.cutcom_maxnum_dummy_blocks);
  if (id == "MD20270") return std::to_string(md.cutting_edge_default);
  if (id == "MD20272") return std::to_string(md.sum_offset_default);
  if (id == "MD22550") return std::to_string(md.tool_change_mode);
  if (id == "MD21000") return md.circle_error_const.to_string();
  if (id == "MD21010") return md.circle_error_factor.to_string();
  return "";
}

}  // namespace cutcom
