// A batch answered in chunks on several threads (the caller's among them), free of pybind11: the
// module (calls.hpp) runs every batched kernel through run_in_chunks. Each element is answered
// alone, so the answers are the same bits for every worker count and chunk size.
#pragma once

#include "batch.hpp"

#include <circledist/effects.hpp>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace circledist::python {

// Elements per chunk: enough chunks for the threads to share unevenly priced elements (a batch
// mixes tangencies with easy cases), each large enough that taking it costs nothing beside it, and
// small enough that the caller sees Ctrl-C soon (it checks between its chunks).
inline Index chunk_size(Index size, int workers) {
  return std::clamp<Index>(size / (Index(workers) * 16), 256, 16384);
}

// Runs work(begin, end) over disjoint chunks covering [0, size), on `workers` threads. Worker
// threads adopt the caller's SelectedEigenPolicy choice, and their counters (stats()) are added to
// the caller's. `interrupted(done)` is asked by the caller's thread after each of its chunks, with
// the count of elements answered so far by every thread (for progress reports): when it answers
// true, no new chunk is started and run_in_chunks returns false once the running ones end.
// An exception in any thread stops the others likewise and is rethrown here.
template <class Work, class Interrupted> bool run_in_chunks(Index size, int workers, Work&& work, Interrupted&& interrupted) {
  const Index chunk = chunk_size(size, workers);
  const int threads = int(std::min<Index>(std::max(workers, 1), (size + chunk - 1) / chunk));
  std::atomic<Index> next{0}, done{0};
  std::atomic<bool> stop{false};
  bool was_interrupted = false;
  std::mutex mutex;
  std::exception_ptr failure;
  Stats others;
  auto take_chunks = [&](bool caller) {
    try {
      while (!stop.load(std::memory_order_relaxed)) {
        const Index begin = next.fetch_add(chunk);
        if (begin >= size) return;
        const Index end = std::min(size, begin + chunk);
        work(begin, end);
        const Index answered = done.fetch_add(end - begin, std::memory_order_relaxed) + (end - begin);
        if (caller && interrupted(answered)) {
          was_interrupted = true;
          stop = true;
        }
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  };
  std::vector<std::thread> pool;
  const SelectedEigenPolicy::Which choice = SelectedEigenPolicy::selected();
  for (int t = 1; t < threads; ++t) {
    try {
      pool.emplace_back([&] {
        const SelectedEigenPolicy::Use use(choice);
        const Stats before = stats();
        take_chunks(false);
        const std::lock_guard<std::mutex> lock(mutex);
        others += stats() - before;
      });
    } catch (const std::system_error&) {  // no more threads to be had: the ones started do the work
      break;
    }
  }
  take_chunks(true);
  for (std::thread& t : pool) t.join();
  stats() += others;
  if (failure) std::rethrow_exception(failure);
  return !was_interrupted;
}

}  // namespace circledist::python
