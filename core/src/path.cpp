#include "cutcom/path.hpp"

#include "text_append.hpp"

namespace cutcom {

std::string_view origin_kind_name(OriginKind k) {
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

namespace {
void append_block_name(std::string& out, int line, const std::optional<std::int64_t>& n) {
  if (n) {
    out += 'N';
    text::append_integer(out, *n);
  } else {
    out += "line ";
    text::append_integer(out, line);
  }
}

// "N40", or for an inserted element "(rounding of N40/N50)", "(turn 2 of N60)" (NC-CONTOUR-*).
void append_inserted_name(std::string& out, int line, const std::optional<std::int64_t>& block,
                          const ContourInsert& insert) {
  switch (insert.kind) {
    case InsertKind::kNone:
      append_block_name(out, line, block);
      return;
    case InsertKind::kRounding:
    case InsertKind::kChamfer:
      out += insert.kind == InsertKind::kRounding ? "(rounding of " : "(chamfer of ";
      append_block_name(out, line, block);
      out += '/';
      append_block_name(out, insert.next_line, insert.next_block);
      out += ')';
      return;
    case InsertKind::kTurn:
      out += "(turn ";
      text::append_integer(out, insert.turn);
      out += " of ";
      append_block_name(out, line, block);
      out += ')';
      return;
  }
}

void append_kind_description(std::string& out, const Origin& o) {
  switch (o.kind) {
    case OriginKind::kProgrammed:
      append_inserted_name(out, o.line, o.block, o.insert);
      out += " without compensation";
      return;
    case OriginKind::kApproach:
      out += "approach ";
      break;
    case OriginKind::kOffset:
      out += "offset of ";
      break;
    case OriginKind::kTransitionCircle:
      out += "transition circle at corner ";
      append_inserted_name(out, o.line, o.block, o.insert);
      out += '/';
      append_inserted_name(out, o.next_line, o.next_block, o.next_insert);
      return;
    case OriginKind::kRetraction:
      out += "retraction ";
      break;
    case OriginKind::kInfeed:
      append_inserted_name(out, o.line, o.block, o.insert);
      out += " at the corner point";
      return;
  }
  append_inserted_name(out, o.line, o.block, o.insert);
}
}  // namespace

std::string_view sar_move_name(SarMove m) {
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

void append_description(std::string& out, const Origin& o) {
  append_kind_description(out, o);
  if (o.sar != SarMove::kNone) {
    out += " (SAR ";
    out += sar_move_name(o.sar);
    out += ')';
  }
}

std::string describe(const Origin& o) {
  std::string text;
  append_description(text, o);
  return text;
}

std::string_view insert_kind_name(InsertKind k) {
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

}  // namespace cutcom
