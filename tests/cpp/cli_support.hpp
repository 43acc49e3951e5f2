#pragma once
// Running the built `hbc` command from a test: exit status, stdout and stderr, and its JSON parsed.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

namespace hbc::test {

struct CliRun {
  int status = -1;  // exit status, -1 when the command did not exit normally
  std::string out, err;
  nlohmann::json json() const { return nlohmann::json::parse(out); }  // throws on bad JSON
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// `hbc ARGS` through the shell (ARGS quoted by the caller where needed).
inline CliRun run_cli(const std::string& args) {
  static int calls = 0;
  const auto base = std::filesystem::temp_directory_path() /
                    ("hbc_cli_run_" + std::to_string(::getpid()) + "_" + std::to_string(calls++));
  const auto out = base.string() + ".out", err = base.string() + ".err";
  const std::string cmd = std::string("'") + HBC_CLI + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace hbc::test
