#pragma once
// A regular file's bytes through a read-only memory map, where the platform has one: no buffer to
// zero and copy into, and the pages come in ahead of the parser. Where there is no map (a pipe, an
// empty file, a platform without mmap), mapped() is false and the caller reads the file itself.
#include <cstddef>
#include <string>
#include <string_view>

namespace hbc::detail {

class FileMap {
 public:
  explicit FileMap(const std::string& path);
  ~FileMap();
  FileMap(const FileMap&) = delete;
  FileMap& operator=(const FileMap&) = delete;
  bool mapped() const { return map_ != nullptr; }
  std::string_view view() const { return {static_cast<const char*>(map_), size_}; }

 private:
  void* map_ = nullptr;
  size_t size_ = 0;
};

}  // namespace hbc::detail
