#include "cutcom/alarm.hpp"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace cutcom {

namespace {
constexpr std::array kCatalogue = {
    AlarmInfo{10740, "too many empty blocks with SAR programming", "SAR-P4-1", false},
    AlarmInfo{10741, "direction reversal with SAR infeed movement", "SAR-DISCL-3", false},
    AlarmInfo{10742, "SAR distance invalid or not programmed", "SAR-DISR-1", false},
    AlarmInfo{10743, "SAR programmed several times", "SAR-AGAIN-1", false},
    AlarmInfo{10744, "no valid SAR direction defined", "SAR-TANGENT-1", false},
    AlarmInfo{10746, "block preprocessing stop with SAR", "SAR-STOP-1", false},
    AlarmInfo{10747, "retraction direction for SAR not defined", "SAR-SIDE-3", false},
    AlarmInfo{10748, "illegal retraction plane with SAR", "SAR-DISRP-2", false},
    AlarmInfo{10750, "tool radius compensation activated without tool number", "TRC-SEL-6", false},
    AlarmInfo{10751, "danger of collision due to tool radius compensation", "TRC-ELEMENT-1", true},
    AlarmInfo{10753, "selection of tool radius compensation only possible in linear block", "TRC-SEL-2", false},
    AlarmInfo{10754, "deselection of tool radius compensation only possible in linear block", "TRC-DESEL-2", false},
    AlarmInfo{10755, "selection of tool radius compensation via KONT not possible at present start point", "TRC-KONT-2",
              false},
    AlarmInfo{10756, "deselection of tool radius compensation via KONT not possible at present end point", "TRC-KONT-2",
              false},
    AlarmInfo{10757, "changing the compensation plane while tool radius compensation is active not possible",
              "TRC-PLANE-1", true},
    AlarmInfo{10762, "too many empty blocks between two traversing blocks with active tool radius compensation",
              "TRC-DUMMY-2", false},
    AlarmInfo{14040, "error in end point of circle", "ARC-CENTRE-2", false},
    AlarmInfo{17181, "D number not defined for the active tool", "TRC-SEL-7", false},
};
}  // namespace

std::span<const AlarmInfo> alarm_catalogue() { return kCatalogue; }

const AlarmInfo* find_alarm(int number) {
  for (const AlarmInfo& a : kCatalogue)
    if (a.number == number) return &a;
  return nullptr;
}

Alarm make_alarm(int number, int line, std::optional<std::int64_t> block, std::string_view clause) {
  const AlarmInfo* info = find_alarm(number);
  if (info == nullptr) throw std::logic_error(fmt::format("alarm {} is not in the catalogue", number));
  Alarm a;
  a.number = number;
  a.line = line;
  a.block = block;
  a.clause = clause.empty() ? info->clause : clause;
  a.text = block ? fmt::format("block N{} (line {}): {}", *block, line, info->text)
                 : fmt::format("line {}: {}", line, info->text);
  return a;
}

}  // namespace cutcom
