#pragma once
// How many threads a stage may split its work over. Every stage takes it as `threads`; results are
// the same for any count. Internal helpers take the resolved copy (count >= 1, grain >= 1) as `par`.
namespace hbc {

namespace detail {
class WorkerPool;
}

// count: threads that may split the work; 0 means the environment variable HBC_THREADS when it holds
// a positive number, else every core of the machine. grain: the fewest elements worth a thread of
// their own (tests lower it to split small meshes into many ranges). pool: worker threads kept for
// one run of steps (set by the run itself, see detail::RunOptions; leave it null).
struct Threads {
  int count = 0;
  int grain = 4096;
  detail::WorkerPool* pool = nullptr;
};

// The thread count `threads` asks for, resolved as described above (always >= 1).
int resolve_threads(const Threads& threads);
// `threads` with count resolved and grain at least 1.
Threads resolved(const Threads& threads);

}  // namespace hbc
