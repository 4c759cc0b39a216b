#pragma once
// Independent tasks 0 .. count-1 on threads, with results that do not depend on the thread count:
// the shelling attempts here, the stars of a local repair (algorithm/local/local_repair.cpp), the
// replay's attempts after a NOBUENOSS (algorithm/expansion/cluster_expansion.cpp) and the corner
// attempts of the boundary generators (generators/boundary_shapes.cpp). It lives in topology,
// which stands alone, because that is the one layer all of them depend on; it knows nothing of
// meshes.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace cmx::topology {

// The threads to run `tasks` tasks on: `requested`, or the machine's cores for 0, at least one
// and no more than the tasks.
inline std::size_t thread_count(std::size_t requested, std::size_t tasks) {
  const std::size_t cores = std::max<std::size_t>(1, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min(requested != 0 ? requested : cores, tasks));
}

// Runs task(i) for i = 0 .. count-1 on `threads` threads (this one included), the indices handed
// out in increasing order by an atomic counter, so that a slow task holds up no other thread.
// task(i) returns true for "done": no index above the lowest done one is started after that
// (tasks already started finish). Returns the lowest done index, or `count` when none is; every
// index below it has run. An exception from a task below it is rethrown once all threads have
// ended (the lowest-indexed one); exceptions above it are dropped, as those tasks' results are.
template <class Task>
std::size_t run_indexed(std::size_t count, std::size_t threads, Task task) {
  std::atomic<std::size_t> next{0}, lowest_done{count};
  std::vector<std::exception_ptr> thrown(count);
  const auto work = [&] {
    for (std::size_t i = next++; i < count && i < lowest_done.load(); i = next++) {
      bool done = false;
      try {
        done = task(i);
      } catch (...) {
        thrown[i] = std::current_exception();
      }
      for (std::size_t low = lowest_done.load();
           done && i < low && !lowest_done.compare_exchange_weak(low, i);) {
      }
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (std::size_t t = 1; t < threads; ++t) helpers.emplace_back(work);
    work();
  }
  const std::size_t lowest = lowest_done.load();
  for (std::size_t i = 0; i < lowest; ++i)
    if (thrown[i]) std::rethrow_exception(thrown[i]);
  return lowest;
}

}  // namespace cmx::topology
