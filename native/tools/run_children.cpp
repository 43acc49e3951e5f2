#include "run_children.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

extern char** environ;

namespace hbc::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Running {
  pid_t pid;
  size_t index;
  std::string out, err;  // the files its stdout and stderr go to
  Clock::time_point start;
};

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::vector<char*> c_strings(std::vector<std::string>& s) {
  std::vector<char*> p;
  for (auto& a : s) p.push_back(a.data());
  p.push_back(nullptr);
  return p;
}

// Starts `self ARGS...` with stdout and stderr to files in `tmp`; pid -1 when it could not start.
Running start(const std::string& self, std::vector<std::string> args, size_t i, const std::string& tmp) {
  Running r{0, i, tmp + "/" + std::to_string(i) + ".out", tmp + "/" + std::to_string(i) + ".err", Clock::now()};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, r.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, r.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  args.insert(args.begin(), self);
  std::vector<char*> argv = c_strings(args);
  if (posix_spawn(&r.pid, self.c_str(), &fa, nullptr, argv.data(), environ) != 0) r.pid = -1;
  posix_spawn_file_actions_destroy(&fa);
  return r;
}

ChildResult collect(const Running& r, int status) {
  ChildResult c;
  c.started = true;
  c.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
  if (WIFEXITED(status)) c.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) c.signal = WTERMSIG(status);
  c.out = slurp(r.out);
  c.err = slurp(r.err);
  std::remove(r.out.c_str());
  std::remove(r.err.c_str());
  return c;
}

}  // namespace

std::string ChildResult::failure(const std::string& otherwise) const {
  if (signal != 0) return "crashed (signal " + std::to_string(signal) + ")";
  std::string msg = err;
  const auto at = msg.rfind("error: ");
  if (at != std::string::npos) msg = msg.substr(at + 7);
  while (!msg.empty() && (msg.back() == '\n' || msg.back() == '\r')) msg.pop_back();
  return msg.empty() ? otherwise : msg;
}

std::string ChildResult::warnings() const {
  std::string out;
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("hbc: warning: ", 0) == 0) out += line + "\n";
  return out;
}

void run_children(const ChildRuns& runs, const std::function<void(size_t, const ChildResult&)>& ended) {
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::string tmpl = "/tmp/" + runs.temp_name + "-XXXXXX";
  if (!mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a temporary folder");
  const std::string tmp = tmpl;
  std::vector<Running> running;
  size_t next = 0;
  while (next < runs.count || !running.empty()) {
    while (next < runs.count && static_cast<int>(running.size()) < runs.jobs) {
      Running r = start(self, runs.args(next), next, tmp);
      if (r.pid < 0) ended(next, ChildResult{});
      else running.push_back(std::move(r));
      ++next;
    }
    if (running.empty()) continue;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    auto it = std::find_if(running.begin(), running.end(), [&](const Running& r) { return r.pid == pid; });
    if (it == running.end()) continue;
    const ChildResult result = collect(*it, status);
    const size_t index = it->index;
    running.erase(it);
    ended(index, result);
  }
  fs::remove_all(tmp);
}

int run_child(const std::vector<std::string>& argv, const std::vector<std::string>& set_env) {
  std::vector<std::string> argv_s = argv, env_s;
  for (char** e = environ; *e; ++e) {
    const std::string_view var(*e);
    const bool replaced = std::any_of(set_env.begin(), set_env.end(), [&](const std::string& s) {
      const std::string name = s.substr(0, s.find('=')) + "=";
      return var.substr(0, name.size()) == name;
    });
    if (!replaced) env_s.push_back(*e);
  }
  env_s.insert(env_s.end(), set_env.begin(), set_env.end());
  std::vector<char*> args = c_strings(argv_s), envp = c_strings(env_s);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv_s[0].c_str(), nullptr, nullptr, args.data(), envp.data()) != 0) return 127;
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace hbc::cli
