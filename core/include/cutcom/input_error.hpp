// Bad input, shared by the reader and the interpreter layer (NC-ERR-1).
#pragma once

#include <stdexcept>
#include <string>

namespace cutcom {

// Bad input: names the 1-based line and column and what is wrong. Exit status 2 in the CLI.
class InputError : public std::runtime_error {
 public:
  InputError(int line, int column, const std::string& what);
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& detail() const { return detail_; }

 private:
  int line_, column_;
  std::string detail_;
};

}  // namespace cutcom
