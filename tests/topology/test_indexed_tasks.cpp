// topology::run_indexed: the lowest task that says done, every task below it run, exceptions
// below it rethrown and above it dropped, whatever the thread count.
#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "topology/indexed_tasks.hpp"

using cmx::topology::run_indexed;
using cmx::topology::thread_count;

TEST_CASE("run_indexed runs every task when none is done, and returns the count") {
  for (std::size_t threads : {1u, 2u, 3u, 8u}) {
    CAPTURE(threads);
    std::vector<std::atomic<int>> ran(50);
    CHECK(run_indexed(ran.size(), threads, [&](std::size_t i) { return ++ran[i], false; }) == ran.size());
    for (const auto& r : ran) CHECK(r.load() == 1);
  }
  CHECK(run_indexed(0, 4, [](std::size_t) { return true; }) == 0);
}

TEST_CASE("run_indexed returns the lowest done task, every task up to it run once") {
  for (std::size_t threads : {1u, 2u, 3u, 8u}) {
    CAPTURE(threads);
    std::vector<std::atomic<int>> ran(60);
    const auto done = [](std::size_t i) { return i == 17 || i == 23 || i == 40; };
    CHECK(run_indexed(ran.size(), threads, [&](std::size_t i) { return ++ran[i], done(i); }) == 17);
    for (std::size_t i = 0; i <= 17; ++i) CHECK(ran[i].load() == 1);
    // Others may have started past it while it ran; on one thread none does.
    if (threads == 1)
      for (std::size_t i = 18; i < ran.size(); ++i) CHECK(ran[i].load() == 0);
  }
}

TEST_CASE("run_indexed rethrows the lowest exception below the lowest done task and drops the others") {
  for (std::size_t threads : {1u, 3u}) {
    CAPTURE(threads);
    const auto throws_at = [&](std::size_t bad, std::size_t done_at) {
      return run_indexed(20, threads, [=](std::size_t i) {
        if (i == bad || i == bad + 4) throw std::runtime_error(std::to_string(i));
        return i == done_at;
      });
    };
    try {
      throws_at(5, 12);
      FAIL("no exception");
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "5");
    }
    CHECK(throws_at(15, 12) == 12);  // above the done task: its result would be dropped too
  }
}

TEST_CASE("thread_count: the request, or the cores for 0, between one and the tasks") {
  CHECK(thread_count(3, 10) == 3);
  CHECK(thread_count(30, 10) == 10);
  CHECK(thread_count(4, 0) == 1);
  CHECK(thread_count(0, 1) == 1);
  CHECK(thread_count(0, 1000) >= 1);
}
