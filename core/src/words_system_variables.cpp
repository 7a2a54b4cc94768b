// NC-LEX-6, TOOL-NAME-1: tool data $TC_DPn[t,d]=v and $TC_TP2[t]="NAME" in a block.
#include "nc_vocabulary.hpp"
#include "word_lexer.hpp"

namespace cutcom::lexer {

// System variables (NC-LEX-6): tool data $TC_DPn[t,d]=v and $TC_TP2[t]="NAME".
void WordLexer::system_variable() {
  std::size_t at = i_;
  ++i_;
  std::string n = letters();
  name_tail(n);
  std::string full = "$" + n;
  std::size_t dp = n.rfind("TC_DP", 0) == 0 ? 5 : 0;
  if (dp) {
    std::string num = n.substr(5);
    int p = 0;
    bool ok = !num.empty() && num.size() <= 2 && std::all_of(num.begin(), num.end(), is_digit);
    if (ok) p = std::stoi(num);
    if (!ok || p < 1 || p > 25) fail(fmt::format("'{}' is not a tool edge parameter ($TC_DP1 … $TC_DP25)", full), at);
    return tool_edge_data(p, at);
  }
  if (n == "TC_TP2") return tool_name_data(at);
  if (n.rfind("TC_SCP", 0) == 0 || n.rfind("TC_ECP", 0) == 0) return sum_offset_data(full, at);
  if (is_machine_output(full)) {  // NC-WORD-7: $A_OUT[n]=v, $A_DBB[n]=v, …: the machine's, kept as written
    index_open(full);
    digits(full + " index");
    index_close();
    if (!equals()) fail(fmt::format("{}[n] is written with '=' (a program cannot read it in cutcom)", full), at);
    number(full + " value");
    return add_text_action(written(at), at);
  }
  if (is_machine_counter(full)) {  // NC-WORD-7: $AC_ACTUAL_PARTS=v, …: the machine's, kept as written
    if (!equals()) fail(fmt::format("{} is written with '=' (a program cannot read it in cutcom)", full), at);
    number(full + " value");
    return add_text_action(written(at), at);
  }
  if (n == "TC_TP1" || n == "TC_TP3" || n == "TC_TP4" || n == "TC_TP5" || n == "TC_TP6" || n == "TC_TP7" ||
      n == "TC_TP8" || n == "TC_TP9" || n == "TC_TP10" || n == "TC_TP11") {
    return ignored_tool_parameter(full);
  }
  fail(fmt::format("system variable '{}' is SINUMERIK NC that cutcom does not simulate (supported: $TC_DP1 … "
                   "$TC_DP25, $TC_TP1 … $TC_TP11, $TC_SCP13 … $TC_SCP71, $TC_ECP13 … $TC_ECP71)",
                   full),
       at);
}

void WordLexer::index_open(std::string_view what) {
  skip_space();
  if (peek() != '[') fail(fmt::format("'[' expected after {}", what));
  ++i_;
  skip_space();
}

void WordLexer::index_close() {
  skip_space();
  if (peek() != ']') fail("']' expected");
  ++i_;
}

// [t,d]= after a tool edge's variable: its tool and edge numbers.
std::pair<std::int64_t, std::int64_t> WordLexer::tool_edge_index(std::string_view what) {
  index_open(what);
  std::int64_t t = digits("tool number");
  skip_space();
  if (peek() != ',') fail(fmt::format("',' expected between tool and edge number (write {}[t,d])", what));
  ++i_;
  skip_space();
  std::int64_t d = digits("edge number");
  index_close();
  if (!equals()) fail("'=' expected");
  return {t, d};
}

void WordLexer::tool_edge_data(int p, std::size_t at) {
  std::string what = fmt::format("$TC_DP{}", p);
  auto [t, d] = tool_edge_index(what);
  Decimal v = number(what + " value");
  if (t < 1 || d < 1) fail("tool and edge numbers start at 1", at);
  if (d > 32000) fail("edge numbers go up to 32000", at);
  if (out_.tool_data_count == BlockWords::kMaxToolData) fail("too many tool data assignments in one block", at);
  out_.tool_data[static_cast<std::size_t>(out_.tool_data_count++)] = {p, static_cast<int>(t), static_cast<int>(d), v};
}

// TOOL-SUM-1: $TC_SCPkp[t,d]=v, $TC_ECPkp[t,d]=v, parameter p (3 … 11, as $TC_DPp) of sum or
// setup offset k (1 … 6), numbered 10 k + p. The lengths and angles leave the path alone; a radius
// part (p = 6) other than 0 would change the radius and is not simulated.
void WordLexer::sum_offset_data(const std::string& full, std::size_t at) {
  std::string num = full.substr(7);
  bool ok = num.size() == 2 && std::all_of(num.begin(), num.end(), is_digit);
  int n = ok ? std::stoi(num) : 0;
  int k = (n - 3) / 10, p = n - 10 * k;
  if (!ok || n < 13 || n > 71 || k < 1 || k > 6 || p < 3 || p > 11)
    fail(fmt::format("'{}' is not a sum offset parameter ({}13 … {}71: 10 × DL + parameter 3 … 11)", full,
                     full.substr(0, 7), full.substr(0, 7)),
         at);
  tool_edge_index(full);
  Decimal v = number(full + " value");
  if (p == 6 && !v.is_zero())
    fail(fmt::format("{}: a sum offset of the radius is SINUMERIK NC that cutcom does not simulate (the sum offsets "
                     "of the lengths leave the path alone)",
                     full),
         at);
  add_text_action(written(at), at);
}

// $TC_TP2[t]="NAME": the tool's name (TOOL-NAME-1).
void WordLexer::tool_name_data(std::size_t at) {
  index_open("$TC_TP2");
  std::int64_t t = digits("tool number");
  index_close();
  if (!equals()) fail("'=' expected");
  if (peek() != '"') fail("$TC_TP2 needs a name in quotes: $TC_TP2[t]=\"NAME\"");
  std::string name = quoted("$TC_TP2");
  if (t < 1) fail("tool numbers start at 1", at);
  if (name.empty()) fail("the tool name is empty", at);
  if (out_.tool_names_count == BlockWords::kMaxToolData) fail("too many tool names in one block", at);
  out_.tool_names[static_cast<std::size_t>(out_.tool_names_count++)] = {static_cast<int>(t), name};
}

// $TC_TP1, $TC_TP3 … $TC_TP11 (duplo number, size, place type, …): no effect on the path.
void WordLexer::ignored_tool_parameter(std::string_view what) {
  index_open(what);
  digits("tool number");
  index_close();
  if (!equals()) fail("'=' expected");
  if (peek() == '"') {
    quoted(what);
    return;
  }
  number(fmt::format("{} value", what));
}

}  // namespace cutcom::lexer
