// The cutcom command line run as a user runs it, for the CLI tests (cli_test.cpp,
// cli_certify_test.cpp): exit status and one output stream of a shell command.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>

namespace cutcom::cli_test {

struct Result {
  int status;
  std::string out;
};

// Runs cmd; its standard output, or with `errors` its standard error, is the result's text.
inline Result sh(const std::string& cmd, bool errors = false) {
  Result r{-1, {}};
  FILE* p = popen((cmd + (errors ? " 2>&1 >/dev/null" : " 2>/dev/null")).c_str(), "r");
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}
inline Result sh_err(const std::string& cmd) { return sh(cmd, true); }

inline const std::string kCli = CUTCOM_CLI;
inline const std::string kExample = CUTCOM_SOURCE_DIR "/examples/pocket.mpf";

// A file in the tests' build directory with `text`; its path.
inline std::string write_temp(const std::string& name, const std::string& text) {
  std::string path = std::string(CUTCOM_BINARY_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace cutcom::cli_test
