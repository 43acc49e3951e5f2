#pragma once
// What the OpenFOAM case reader (foam_case.cpp) and the decomposed-case join
// (read_foam_decomposed.cpp) share: a polyMesh file's bytes, plain or gzip'd, and labelList files.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "platform/file_map.hpp"

namespace hbc::detail {

// One file's bytes: mapped when plain, inflated when .gz.
struct FileText {
  std::string name;
  std::unique_ptr<FileMap> map;
  std::string bytes;
  std::string_view view() const { return map && map->mapped() ? map->view() : std::string_view(bytes); }
};

// `dir`/name, or name.gz inflated; InputError naming `what` ("polyMesh file") when neither exists.
FileText mesh_file(const std::filesystem::path& dir, const char* name, const char* what = "polyMesh file");

// The polyMesh folder of the newest time folder of case `c` that holds one, else constant/polyMesh;
// empty when there is neither.
std::filesystem::path case_mesh(const std::filesystem::path& c);

// A labelList file's labels (ASCII or binary, uniform lists too); with `locs` the line (byte offset
// when `*binary`) of each. InputError naming `source` and the place for anything else.
std::vector<int64_t> read_foam_labels(std::string_view bytes, const std::string& source,
                                      std::vector<int64_t>* locs = nullptr, bool* binary = nullptr);

}  // namespace hbc::detail
