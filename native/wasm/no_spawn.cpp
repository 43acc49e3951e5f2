// A WebAssembly program cannot start processes, and emscripten's libc has no posix_spawnp: the
// commands that run other programs get ENOSYS and report it as any failed start.
#include <cerrno>
#include <spawn.h>

extern "C" int posix_spawnp(pid_t*, const char*, const posix_spawn_file_actions_t*, const posix_spawnattr_t*,
                            char* const[], char* const[]) {
  return ENOSYS;
}
