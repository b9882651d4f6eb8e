// Spare hands of a thread pool: loops over independent items whose chunks the pool's idle workers may take.
//
// A duty cycle runs its scenarios on a few workers; the longest scenario (straight plowing's 20-s record)
// outlasts the others, and its worker would finish alone. Its station-by-station work (section forces,
// stresses, hot spots, the life map) is a loop over independent items: posted here, the workers that have
// no scenario left take chunks of it. Each item writes its own slot, so the results are the same numbers
// on any number of workers, in any order of chunks (docs/theory/fatigue.md, section 16).
//
// The thread that posts a loop works through it too and returns when every chunk is done; a worker that
// calls help() takes chunks of whichever loops are posted until its `finished` test says no loop will come.
// An exception thrown by a chunk is rethrown by for_ranges in the posting thread (the first, by chunk order).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <list>
#include <mutex>

namespace framedyn::core {

class WorkShare {
 public:
  using Body = std::function<void(std::size_t begin, std::size_t end)>;

  // body(begin, end) over [0, n) in chunks of at most `grain` items; the calling thread takes part.
  void for_ranges(std::size_t n, std::size_t grain, const Body& body);

  // An idle worker: takes chunks of posted loops, and waits for more, until finished() is true.
  // finished() is tested under the share's lock; call wake() after whatever it reads has changed.
  void help(const std::function<bool()>& finished);
  void wake();

  // Chunks taken by threads other than the loop's own (for tests: a helper did join).
  std::size_t shared_chunks() const;

 private:
  struct Loop;
  bool work_on(Loop& loop, std::unique_lock<std::mutex>& lock);  // one chunk, taken and run without the lock
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::list<Loop*> posted_;
  std::size_t shared_chunks_ = 0;
};

// body over [0, n) on `share` when there is one, else in the calling thread in one range.
void for_ranges(WorkShare* share, std::size_t n, std::size_t grain, const WorkShare::Body& body);

}  // namespace framedyn::core
