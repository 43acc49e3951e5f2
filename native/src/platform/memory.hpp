#pragma once
// Handing freed memory back to the system between stages, where the allocator allows it.
namespace hbc::detail {

// Returns the heap's free pages to the system: glibc keeps arrays below its mmap threshold (up to
// 32 MB) in heaps whose pages a free() keeps unless they are at the top. Nothing elsewhere.
void return_freed_memory();

}  // namespace hbc::detail
