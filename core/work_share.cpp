// Spare hands of a thread pool; see work_share.h.
#include "core/work_share.h"

#include <algorithm>

namespace framedyn::core {

struct WorkShare::Loop {
  std::size_t n = 0, grain = 1;
  const Body* body = nullptr;
  std::size_t next = 0;     // the first item not yet handed out
  std::size_t running = 0;  // chunks handed out and not finished
  std::exception_ptr error;
  std::size_t error_at = 0;  // the first item of the failed chunk (the earliest kept)
};

bool WorkShare::work_on(Loop& loop, std::unique_lock<std::mutex>& lock) {
  if (loop.next >= loop.n) return false;
  const std::size_t begin = loop.next, end = std::min(loop.n, begin + loop.grain);
  loop.next = end;
  ++loop.running;
  lock.unlock();
  std::exception_ptr error;
  try {
    (*loop.body)(begin, end);
  } catch (...) {
    error = std::current_exception();
  }
  lock.lock();
  if (error) {
    if (!loop.error || begin < loop.error_at) loop.error = error, loop.error_at = begin;
    loop.next = loop.n;  // no more chunks: the loop has failed
  }
  if (--loop.running == 0) changed_.notify_all();  // the poster may be waiting for the last chunk
  return true;
}

void WorkShare::for_ranges(std::size_t n, std::size_t grain, const Body& body) {
  if (n == 0) return;
  Loop loop;
  loop.n = n;
  loop.grain = std::max<std::size_t>(1, grain);
  loop.body = &body;
  std::unique_lock<std::mutex> lock(mutex_);
  posted_.push_back(&loop);
  changed_.notify_all();
  while (work_on(loop, lock)) {
  }
  posted_.remove(&loop);
  changed_.wait(lock, [&] { return loop.running == 0; });
  lock.unlock();
  if (loop.error) std::rethrow_exception(loop.error);
}

void WorkShare::help(const std::function<bool()>& finished) {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!finished()) {
    Loop* open = nullptr;
    for (Loop* l : posted_)
      if (l->next < l->n) {
        open = l;
        break;
      }
    if (!open) {
      changed_.wait(lock);
      continue;
    }
    ++shared_chunks_;
    work_on(*open, lock);
  }
}

void WorkShare::wake() {
  const std::lock_guard<std::mutex> lock(mutex_);
  changed_.notify_all();
}

std::size_t WorkShare::shared_chunks() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return shared_chunks_;
}

void for_ranges(WorkShare* share, std::size_t n, std::size_t grain, const WorkShare::Body& body) {
  if (share) share->for_ranges(n, grain, body);
  else if (n > 0) body(0, n);
}

}  // namespace framedyn::core
