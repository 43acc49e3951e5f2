#include "platform/file_map.hpp"

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define HBC_HAVE_MMAP 1
#endif

namespace hbc::detail {

#if defined(HBC_HAVE_MMAP) && !defined(__EMSCRIPTEN__)
FileMap::FileMap(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    const size_t size = static_cast<size_t>(st.st_size);
#if defined(MAP_POPULATE)
    const int flags = MAP_PRIVATE | MAP_POPULATE;
#else
    const int flags = MAP_PRIVATE;
#endif
    void* p = ::mmap(nullptr, size, PROT_READ, flags, fd, 0);
    if (p != MAP_FAILED) {
      map_ = p;
      size_ = size;
    }
  }
  ::close(fd);
}

FileMap::~FileMap() {
  if (map_) ::munmap(map_, size_);
}
#else
// No memory maps here: the caller reads the file.
FileMap::FileMap(const std::string&) {}
FileMap::~FileMap() = default;
#endif

}  // namespace hbc::detail
