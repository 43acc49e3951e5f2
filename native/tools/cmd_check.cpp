// hbc check FILE [--json]: every defect class of a file's cells with its count and first cells,
// faces or vertices, with their lines (docs/check.md). Exit status 0 clean, 1 defects found, 2 a
// file that cannot be read (hbc_main.cpp maps InputError to 2).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "commands.hpp"
#include "hbc/check.hpp"
#include "hbc/json.hpp"
#include "hbc/report.hpp"

namespace hbc::cli {
namespace {

struct CheckArgs {
  InputArgs input;
  bool json = false;
  int listed = 10;
};

bool has_volume(Defect d) { return d == Defect::Inverted || d == Defect::ZeroVolume; }

Json item_json(Defect d, const DefectItem& it) {
  Json j = {{"id", it.id}};
  if (it.loc.line >= 0) j["line"] = it.loc.line;
  if (it.loc.byte_offset >= 0) j["byte"] = it.loc.byte_offset;
  if (has_volume(d)) j["volume"] = it.volume;
  return j;
}

Json report_json(const CheckReport& r) {
  Json defects = Json::object();
  for (size_t k = 0; k < kDefectCount; ++k) {
    const auto d = static_cast<Defect>(k);
    Json first = Json::array();
    for (const DefectItem& it : r[d].first) first.push_back(item_json(d, it));
    defects[defect_key(d)] = {{"count", r[d].count},     {"of", defect_subject(d)}, {"refused", defect_refused(d)},
                              {"dropped", r[d].dropped}, {"first", first}};
  }
  Json j = {{"file", r.source}, {"vertices", r.vertices}, {"cells", r.cells}, {"clean", r.clean()}, {"defects", defects}};
  add_dropped_json(j, true, r.dropped);  // the very object of `hbc analyze --skip-invalid --json`
  return j;
}

// What --skip-invalid does to a class: every element goes, some of them, or none.
std::string dropped_note(const DefectClass& k) {
  if (k.dropped == 0) return "";
  if (k.dropped == k.count) return " [refused; --skip-invalid drops them]";
  return " [--skip-invalid drops " + std::to_string(k.dropped) + " of them]";
}

std::string item_text(Defect d, const DefectItem& it) {
  std::string s = std::to_string(it.id);
  if (it.loc.line >= 0) s += " (line " + std::to_string(it.loc.line) + ")";
  else if (it.loc.byte_offset >= 0) s += " (byte " + std::to_string(it.loc.byte_offset) + ")";
  if (has_volume(d)) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " volume %.3g", it.volume);
    s += buf;
  }
  return s;
}

void print_text(const CheckReport& r, size_t listed) {
  std::printf("%s: %lld vertices, %lld cells: %s\n", r.source.c_str(), static_cast<long long>(r.vertices),
              static_cast<long long>(r.cells), r.clean() ? "no defects" : "defects found");
  for (size_t k = 0; k < kDefectCount; ++k) {
    const auto d = static_cast<Defect>(k);
    if (r[d].count == 0) continue;
    std::string ids;
    for (const DefectItem& it : r[d].first) ids += (ids.empty() ? "" : ", ") + item_text(d, it);
    if (static_cast<size_t>(r[d].count) > r[d].first.size()) ids += ", ...";
    std::printf("  %-20s %8lld %s%s: %s %s\n", defect_key(d), static_cast<long long>(r[d].count), defect_title(d),
                dropped_note(r[d]).c_str(), defect_subject(d), ids.c_str());
  }
  // The sentence the load itself warns with (dropped_summary), on the same list.
  if (!r.dropped.empty()) std::printf("with --skip-invalid: %s\n", dropped_summary(r.dropped, listed).c_str());
}

void run_check(const CheckArgs& args) {
  const CheckReport r = check_file(args.input.file, args.input.parsed_format(), static_cast<size_t>(args.listed),
                                   args.input.load_threads());
  if (args.json) write_output(json_text(report_json(r)), std::nullopt);
  else print_text(r, static_cast<size_t>(args.listed));
  std::fflush(stdout);
  if (!r.clean()) std::exit(1);  // defects found: the status scripts test
}

}  // namespace

void add_check(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = add_mesh_command(app, "check", "defects of a file's cells by class, with lines (exit 0 clean, 1 defects, 2 unreadable)",
                                   args->input, args->json, "print the report as JSON");
  cmd->add_option("--first", args->listed, "how many elements to list per defect class")->check(at_least(0))->capture_default_str();
  cmd->callback([args] { run_check(*args); });
}

}  // namespace hbc::cli
