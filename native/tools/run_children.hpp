#pragma once
// Child processes of the hbc command: the one file of the CLI that starts and waits for them
// (POSIX spawn and waitpid). `hbc table` and `hbc compare` measure each mesh in a child of this
// executable, N at a time, so that a mesh that fails (bad input, crash, out of memory) fails its
// own row or column alone; `hbc compare` runs its report's Python as one more child. A WebAssembly
// program cannot start processes (native/wasm/no_spawn.cpp): every child there fails to start.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace hbc::cli {

// How one child ended.
struct ChildResult {
  bool started = false;    // false: it could not be started, and nothing below is set
  int exit_code = -1;      // its exit status when it exited, else -1
  int signal = 0;          // the signal that ended it, else 0
  std::string out, err;    // what it wrote on stdout and on stderr
  double seconds = 0;      // from its start to its end
  bool succeeded() const { return started && signal == 0 && exit_code == 0; }
  // Why a child that ran failed: "crashed (signal N)", else its last "error: " line (the warnings
  // before it are not the reason), else `otherwise`.
  std::string failure(const std::string& otherwise) const;
  // Its "hbc: warning: " lines (each naming its file), for the parent to repeat.
  std::string warnings() const;
};

struct ChildRuns {
  size_t count = 0;         // children 0 .. count-1
  int jobs = 1;             // running at once
  std::string temp_name;    // their outputs go to /tmp/<temp_name>-XXXXXX, removed at the end
  // The arguments of child i after this executable's path.
  std::function<std::vector<std::string>(size_t)> args;
};

// Runs this executable once per child, `jobs` at a time, started in index order; `ended(i, result)`
// is called on this thread as each one ends (a child that cannot start, at once). Throws
// std::runtime_error when the temporary folder cannot be made.
void run_children(const ChildRuns& runs, const std::function<void(size_t, const ChildResult&)>& ended);

// Runs `argv` (argv[0] searched on PATH) in this process's environment with `set_env` ("NAME=value"
// each) in place of those variables, its messages on our stderr, and waits for it: its exit status,
// 128 + the signal that ended it, or 127 when it could not start.
int run_child(const std::vector<std::string>& argv, const std::vector<std::string>& set_env);

}  // namespace hbc::cli
