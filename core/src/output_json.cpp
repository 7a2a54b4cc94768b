#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "cutcom/output.hpp"

namespace cutcom {

namespace {
using nlohmann::json;

double clean(double v) { return v == 0 ? 0.0 : v; }  // never print -0

json point(const PathPoint& p) { return json::array({clean(p.x), clean(p.y), clean(p.z)}); }

json block_ref(const std::optional<std::int64_t>& b) { return b ? json(*b) : json(nullptr); }

void append(std::string& list, const json& item) {
  if (!list.empty()) list += ",\n    ";
  list += item.dump();
}
}  // namespace

JsonWriter::JsonWriter(std::ostream& out, std::string engine, bool with_trace) : out_(out), with_trace_(with_trace) {
  out_ << "{\n  \"format\": \"cutcom-path/1\",\n  \"engine\": " << json(engine).dump()
       << ",\n  \"unit\": \"mm\",\n  \"path\": [";
}

void JsonWriter::element(const PathElement& e) {
  json j;
  j["type"] = e.type == ElementType::kLine ? "line" : "arc";
  j["rapid"] = e.rapid;
  j["start"] = point(e.start);
  j["end"] = point(e.end);
  if (e.type == ElementType::kArc) {
    j["center"] = point(e.center);
    j["ccw"] = e.ccw;
  }
  j["line"] = e.origin.line;
  j["block"] = block_ref(e.origin.block);
  json o;
  o["kind"] = origin_kind_name(e.origin.kind);
  o["line"] = e.origin.line;
  if (e.origin.kind == OriginKind::kTransitionCircle) o["next_line"] = e.origin.next_line;
  if (e.origin.sar != SarMove::kNone) o["sar"] = sar_move_name(e.origin.sar);
  if (e.origin.insert.kind != InsertKind::kNone) {  // NC-CONTOUR-*: an element the reader inserted
    o["inserted"] = insert_kind_name(e.origin.insert.kind);
    if (e.origin.insert.kind == InsertKind::kTurn)
      o["turn"] = e.origin.insert.turn;
    else
      o["corner_next_line"] = e.origin.insert.next_line;
  }
  o["text"] = describe(e.origin);
  if (e.origin.source != 0 && sources_) o["source"] = sources_(e.origin.source);  // NC-PARAM-SUB-3
  j["origin"] = o;
  if (!e.rapid) j["feed"] = e.feed.to_string();
  if (!e.rapid && e.feed_type == FeedType::kG95) j["feed_type"] = "G95";
  out_ << (first_ ? "\n    " : ",\n    ") << j.dump();
  first_ = false;
}

void JsonWriter::action(const ActionEvent& a) {
  append(actions_,
         json{{"line", a.line}, {"block", block_ref(a.block)}, {"function", a.function.name()}, {"at", point(a.at)}});
}

void JsonWriter::decision(const Decision& d) {
  if (!with_trace_) return;
  json j{{"clause", d.clause}, {"line", d.line}, {"branch", d.branch}};
  if (d.has_margin) {
    if (!d.margin_exact.empty())
      j["margin_exact"] = d.margin_exact;
    else
      j["margin"] = clean(d.margin);
  }
  append(decisions_, j);
}

void JsonWriter::alarm(const Alarm& a) {
  json j{{"number", a.number}, {"line", a.line}, {"block", block_ref(a.block)}, {"clause", a.clause}, {"text", a.text}};
  if (a.source != 0 && sources_) j["source"] = sources_(a.source);  // NC-PARAM-SUB-3
  append(alarms_, j);
}

void JsonWriter::notice(const Notice& n) {
  append(notices_, json{{"line", n.line}, {"clause", n.clause}, {"text", n.text}});
}

void JsonWriter::sar_variables(const SarVariables& v) {
  append(variables_, json{{"line", v.line},
                          {"block", block_ref(v.block)},
                          {"$P_APR", point(v.p_apr)},
                          {"$P_AEP", point(v.p_aep)},
                          {"$P_APDV", v.p_apdv}});
}

void JsonWriter::finish() {
  out_ << (first_ ? "]" : "\n  ]");
  auto list = [&](const char* key, const std::string& items) {
    out_ << ",\n  \"" << key << "\": [" << (items.empty() ? "" : "\n    " + items + "\n  ") << "]";
  };
  list("actions", actions_);
  list("alarms", alarms_);
  list("notices", notices_);
  list("variables", variables_);
  if (with_trace_) list("decisions", decisions_);
  out_ << "\n}\n";
}

}  // namespace cutcom
