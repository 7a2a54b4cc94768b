#include "cutcom/path.hpp"

#include <fmt/format.h>

namespace cutcom {

std::string origin_kind_name(OriginKind k) {
  switch (k) {
    case OriginKind::kProgrammed:
      return "programmed";
    case OriginKind::kApproach:
      return "approach";
    case OriginKind::kOffset:
      return "offset";
    case OriginKind::kTransitionCircle:
      return "transition_circle";
    case OriginKind::kRetraction:
      return "retraction";
    case OriginKind::kInfeed:
      return "infeed";
  }
  return "?";
}

std::string describe_kind(const Origin& o);

namespace {
std::string block_name(int line, const std::optional<std::int64_t>& n) {
  return n ? fmt::format("N{}", *n) : fmt::format("line {}", line);
}
}  // namespace

std::string sar_move_name(SarMove m) {
  switch (m) {
    case SarMove::kNone:
      return "";
    case SarMove::kLead:
      return "lead";
    case SarMove::kFastInfeed:
      return "fast_infeed";
    case SarMove::kSlowInfeed:
      return "slow_infeed";
    case SarMove::kElement:
      return "element";
    case SarMove::kEndPath:
      return "end_path";
  }
  return "?";
}

std::string describe(const Origin& o) {
  std::string text = describe_kind(o);
  if (o.sar != SarMove::kNone) text += fmt::format(" (SAR {})", sar_move_name(o.sar));
  return text;
}

// "N40", or for an inserted element "(rounding of N40/N50)", "(turn 2 of N60)" (NC-CONTOUR-*).
std::string inserted_name(int line, const std::optional<std::int64_t>& block, const ContourInsert& insert) {
  std::string b = block_name(line, block);
  const ContourInsert& o = insert;
  switch (o.kind) {
    case InsertKind::kNone:
      return b;
    case InsertKind::kRounding:
      return fmt::format("(rounding of {}/{})", b, block_name(o.next_line, o.next_block));
    case InsertKind::kChamfer:
      return fmt::format("(chamfer of {}/{})", b, block_name(o.next_line, o.next_block));
    case InsertKind::kTurn:
      return fmt::format("(turn {} of {})", o.turn, b);
  }
  return b;
}

std::string insert_kind_name(InsertKind k) {
  switch (k) {
    case InsertKind::kNone:
      return "";
    case InsertKind::kRounding:
      return "rounding";
    case InsertKind::kChamfer:
      return "chamfer";
    case InsertKind::kTurn:
      return "turn";
  }
  return "?";
}

std::string describe_kind(const Origin& o) {
  std::string b = inserted_name(o.line, o.block, o.insert);
  switch (o.kind) {
    case OriginKind::kProgrammed:
      return fmt::format("{} without compensation", b);
    case OriginKind::kApproach:
      return fmt::format("approach {}", b);
    case OriginKind::kOffset:
      return fmt::format("offset of {}", b);
    case OriginKind::kTransitionCircle:
      return fmt::format("transition circle at corner {}/{}", b,
                         inserted_name(o.next_line, o.next_block, o.next_insert));
    case OriginKind::kRetraction:
      return fmt::format("retraction {}", b);
    case OriginKind::kInfeed:
      return fmt::format("{} at the corner point", b);
  }
  return b;
}

}  // namespace cutcom
