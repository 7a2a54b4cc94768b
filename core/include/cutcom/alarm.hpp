// The alarm catalogue (spec ALARM-*): number, text and the clause that raises it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace cutcom {

struct AlarmInfo {
  int number;
  std::string_view text;
  std::string_view clause;  // spec clause that raises it
  bool number_confirmed;    // false: number from the diagnostics list, not from the retrieved manual pages
};

// nullptr for a number not in the catalogue.
const AlarmInfo* find_alarm(int number);
// The whole catalogue, in number order.
std::span<const AlarmInfo> alarm_catalogue();

// An alarm raised while running a program; it stops the program (the path before it is kept).
struct Alarm {
  int number = 0;
  int line = 0;                       // 1-based source line of the block that raised it
  std::optional<std::int64_t> block;  // its N number, if programmed
  std::string_view clause;
  std::string text;          // catalogue text, completed with the block
  std::uint32_t source = 0;  // NC-PARAM-SUB-3: where in a subprogram the block stands (0: the line)
};

// `clause` names the raising clause where the catalogue's (the usual one) is not it.
Alarm make_alarm(int number, int line, std::optional<std::int64_t> block, std::string_view clause = {});

// Something a user should know that does not stop the program.
struct Notice {
  int line = 0;
  std::string_view clause;
  std::string text;
  std::uint32_t source = 0;  // NC-PARAM-SUB-3, as an alarm's
};

}  // namespace cutcom
