#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"

namespace hbc::cli {

bool take_flag(Args& args, const std::string& flag) {
  auto it = std::find(args.begin(), args.end(), flag);
  if (it == args.end()) return false;
  args.erase(it);
  return true;
}

std::optional<std::string> take_option(Args& args, const std::string& opt) {
  auto it = std::find(args.begin(), args.end(), opt);
  if (it == args.end()) return std::nullopt;
  if (it + 1 == args.end()) throw std::invalid_argument(opt + " needs a value");
  std::string v = *(it + 1);
  args.erase(it, it + 2);
  return v;
}

InputFormat take_format(Args& args) {
  InputFormat in;
  if (auto f = take_option(args, "--format")) in.format = format_from_name(*f);
  if (auto t = take_option(args, "--threads")) {
    int n = 0;
    const char* end = t->data() + t->size();
    const auto r = std::from_chars(t->data(), end, n);
    if (r.ec != std::errc() || r.ptr != end || n < 1 || n > 1024)
      throw std::invalid_argument("--threads takes a whole number in [1, 1024], found '" + *t + "'");
    in.load.threads = n;
  }
  return in;
}

Mesh load_for_cli(const std::string& path, const InputFormat& format, double* seconds) {
  auto t0 = std::chrono::steady_clock::now();
  Mesh m = load_mesh(path, format.format, format.load);
  auto t1 = std::chrono::steady_clock::now();
  if (seconds) *seconds = std::chrono::duration<double>(t1 - t0).count();
  for (const auto& w : m.warnings) std::fprintf(stderr, "hbc: warning: %s: %s\n", path.c_str(), w.c_str());
  return m;
}

}  // namespace hbc::cli
