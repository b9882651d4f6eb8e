// core::WorkShare (core/work_share.h): a loop's chunks taken by the poster and by an idle worker.
// The duty cycle's frame studies rest on three facts checked here: every item of a loop is done
// exactly once whoever takes it, an idle worker does take chunks while the poster works, and a
// chunk's exception reaches the thread that posted the loop.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/work_share.h"

namespace {

using framedyn::core::WorkShare;

// A helper thread in help() until the test says it is done.
struct Helper {
  WorkShare& share;
  std::atomic<bool> done{false};
  std::thread thread;
  explicit Helper(WorkShare& s) : share(s), thread([this] { share.help([this] { return done.load(); }); }) {}
  ~Helper() {
    done = true;
    share.wake();
    thread.join();
  }
};

// The poster's first chunk waits until another thread has started a chunk: the helper must have
// joined for the loop to end (a 30-s guard turns a helper that never joins into a failure, not a hang).
TEST(WorkShare, AnIdleWorkerTakesChunksAndEveryItemIsDoneOnce) {
  WorkShare share;
  Helper helper(share);
  const std::size_t n = 1000;
  std::vector<std::atomic<int>> visits(n);
  const std::thread::id poster = std::this_thread::get_id();
  std::atomic<bool> other_started{false}, timed_out{false};
  share.for_ranges(n, 7, [&](std::size_t begin, std::size_t end) {
    if (std::this_thread::get_id() != poster) other_started = true;
    if (begin == 0) {
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
      while (!other_started && std::chrono::steady_clock::now() < until) std::this_thread::yield();
      timed_out = !other_started;
    }
    for (std::size_t i = begin; i < end; ++i) ++visits[i];
  });
  EXPECT_FALSE(timed_out);
  EXPECT_GT(share.shared_chunks(), 0u);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(visits[i].load(), 1) << "item " << i;
}

TEST(WorkShare, AChunksExceptionReachesThePoster) {
  WorkShare share;
  Helper helper(share);
  EXPECT_THROW(share.for_ranges(100, 1,
                                [&](std::size_t begin, std::size_t) {
                                  if (begin == 3) throw std::runtime_error("chunk 3");
                                }),
               std::runtime_error);
  // The loop can be posted again afterwards: the share holds no failed loop.
  std::atomic<std::size_t> items{0};
  share.for_ranges(10, 3, [&](std::size_t begin, std::size_t end) { items += end - begin; });
  EXPECT_EQ(items.load(), 10u);
}

TEST(WorkShare, WithoutAShareTheBodyRunsOnceOverTheWholeRange) {
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  framedyn::core::for_ranges(nullptr, 42, 5, [&](std::size_t begin, std::size_t end) { calls.emplace_back(begin, end); });
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0], std::make_pair(std::size_t{0}, std::size_t{42}));
  framedyn::core::for_ranges(nullptr, 0, 5, [&](std::size_t, std::size_t) { calls.emplace_back(9, 9); });
  EXPECT_EQ(calls.size(), 1u);  // an empty range: no call
}

}  // namespace
