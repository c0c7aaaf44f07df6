// A batch answered in chunks on several threads (the caller's among them), free of pybind11: the
// module (bindings/calls.hpp) runs every batched kernel through run_in_chunks. Each element is answered
// alone, so the answers are the same bits for every worker count and chunk size.
#pragma once

#include "batch.hpp"

#include <circledist/effects.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace circledist::python {

// Elements per chunk at most: enough chunks for the threads to share unevenly priced elements (a
// batch mixes tangencies with easy cases), each large enough that taking it costs nothing beside
// it.
inline Index chunk_size(Index size, int workers) { return std::clamp<Index>(size / (Index(workers) * 16), 256, 16384); }

// And in time: the caller's first chunk is small (kFirstChunk elements) and timed, and the chunks
// after it are sized to take about kChunkTime, so that the caller, which checks for Ctrl-C and
// reports progress between its chunks, does so every few milliseconds however dear the elements
// (16384 Bezier-disk queries took a fifth of a second, more on a busy machine).
constexpr Index kFirstChunk = 64;
constexpr std::chrono::microseconds kChunkTime{10000};

// Runs work(begin, end) over disjoint chunks covering [0, size), on `workers` threads. Worker
// threads adopt the caller's SelectedEigenPolicy choice, and their counters (stats()) are added to
// the caller's. `interrupted(done)` is asked by the caller's thread after each of its chunks, with
// the count of elements answered so far by every thread (for progress reports): when it answers
// true, no new chunk is started and run_in_chunks returns false once the running ones end.
// An exception in any thread stops the others likewise and is rethrown here. A caller that keeps
// per-chunk state gives `fixed_chunk`: every chunk then starts at a multiple of it.
template <class Work, class Interrupted>
bool run_in_chunks(Index size, int workers, Work&& work, Interrupted&& interrupted, Index fixed_chunk = 0) {
  const Index largest = fixed_chunk > 0 ? fixed_chunk : chunk_size(size, workers);
  const int threads = int(std::min<Index>(std::max(workers, 1), (size + largest - 1) / largest));
  std::atomic<Index> next{0}, done{0}, chunk{fixed_chunk > 0 ? fixed_chunk : std::min(kFirstChunk, largest)};
  bool sized = fixed_chunk > 0;  // the caller has timed its first chunk (or the size is fixed)
  std::atomic<bool> stop{false};
  bool was_interrupted = false;
  std::mutex mutex;
  std::exception_ptr failure;
  Stats others;
  auto take_chunks = [&](bool caller) {
    try {
      while (!stop.load(std::memory_order_relaxed)) {
        const Index step = chunk.load(std::memory_order_relaxed);
        const Index begin = next.fetch_add(step);
        if (begin >= size) return;
        const Index end = std::min(size, begin + step);
        const bool timed = caller && !sized;
        const auto started = timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
        work(begin, end);
        if (timed) {
          sized = true;
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
          const double per_element = seconds / double(end - begin);
          const double wanted = std::chrono::duration<double>(kChunkTime).count() / std::max(per_element, 1e-12);
          chunk.store(Index(std::clamp<double>(wanted, double(kFirstChunk), double(largest))),
                      std::memory_order_relaxed);
        }
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
