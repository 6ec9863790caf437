// Copyright 2026 The draco-uv Authors.
//
// Licensed under the Apache License, Version 2.0 (the "License");
// you may not use this file except in compliance with the License.
// You may obtain a copy of the License at
//
//      http://www.apache.org/licenses/LICENSE-2.0
//
// Unless required by applicable law or agreed to in writing, software
// distributed under the License is distributed on an "AS IS" BASIS,
// WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
// See the License for the specific language governing permissions and
// limitations under the License.
//
// Items of a sequence computed ahead of their consumer on a second thread.
#ifndef PREDICTION_SCHEMES_WEIGHTED_UV_LOOKAHEAD_H_
#define PREDICTION_SCHEMES_WEIGHTED_UV_LOOKAHEAD_H_

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "draco/core/macros.h"
#include "draco_ext/common/threads.h"

// Keeps a function out of the loops that call it: for the once-per-chunk
// work, which inlined into the consumer's per-item loop made that loop
// slower (2 % more decode instructions of the weighted schemes with GCC).
#if defined(__GNUC__) || defined(__clang__)
#define DRACO_UV_LOOKAHEAD_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define DRACO_UV_LOOKAHEAD_NOINLINE __declspec(noinline)
#else
#define DRACO_UV_LOOKAHEAD_NOINLINE
#endif

namespace draco {

// Provides items 0 .. n - 1 of a sequence, in increasing order, where item
// i is a pure function of i (it must not read anything the consumer
// writes). Items are computed in chunks of kChunk by |compute|(begin, end,
// out), a ComputeT (a lambda's type: called directly, without the type
// erasure of std::function, the default). With |use_second_thread|, a
// second thread (SecondThread) claims
// chunks in order and computes them ahead. The consumer never waits for
// it: it computes a chunk itself when it reaches one the thread has not
// finished (claiming it if the thread has not started it), so a thread
// that starts late or is descheduled costs at most some duplicated work.
// Whoever computes an item, it is the same, so nothing depends on timing.
//
// Memory: all n items with the second thread, one chunk without. Weak
// where: asked for a second thread when none is available
// (SecondThreadAvailable()), the constructor computes all n items itself
// before it returns, so callers ask only when one is. Builds without threads
// (kBuildHasThreads) contain no thread code.
template <typename T,
          class ComputeT = std::function<void(int begin, int end, T *out)>>
class UvLookahead {
 public:
  static constexpr int kChunk = 256;

  UvLookahead(int n, bool use_second_thread, ComputeT compute)
      : n_(n),
        num_chunks_((n + kChunk - 1) / kChunk),
        threaded_(kBuildHasThreads && use_second_thread && num_chunks_ > 1),
        compute_(std::move(compute)),
        own_chunk_(new T[kChunk]) {
    if constexpr (kBuildHasThreads) {
      if (threaded_) {
        items_.reset(new T[n]);
        done_.reset(new std::atomic<uint8_t>[num_chunks_]);
        for (int c = 0; c < num_chunks_; ++c) {
          done_[c].store(0, std::memory_order_relaxed);
        }
        worker_.emplace([this] { RunWorker(); });
      }
    }
  }

  ~UvLookahead() {
    if (kBuildHasThreads && threaded_) {
      // Stops the worker claiming more chunks (the consumer may stop early).
      next_chunk_.store(num_chunks_);
      worker_->Join();
    }
  }

  UvLookahead(const UvLookahead &) = delete;
  UvLookahead &operator=(const UvLookahead &) = delete;

  // Item |i|; calls must not decrease |i|.
  const T &Get(int i) {
    DRACO_DCHECK(i >= 0 && i < n_);
    const int chunk = i / kChunk;
    if (chunk != current_chunk_) {
      DRACO_DCHECK_GT(chunk, current_chunk_);
      MakeAvailable(chunk);
      current_chunk_ = chunk;
    }
    return current_[i - chunk * kChunk];
  }

 private:
  void ComputeChunk(int chunk, T *out) const {
    compute_(chunk * kChunk, std::min(n_, (chunk + 1) * kChunk), out);
  }

  void RunWorker() {
    for (int chunk = next_chunk_.fetch_add(1); chunk < num_chunks_;
         chunk = next_chunk_.fetch_add(1)) {
      ComputeChunk(chunk, items_.get() + chunk * kChunk);
      done_[chunk].store(1, std::memory_order_release);
    }
  }

  // Points current_ at the items of |chunk|.
  DRACO_UV_LOOKAHEAD_NOINLINE void MakeAvailable(int chunk) {
    if (threaded_ && done_[chunk].load(std::memory_order_acquire)) {
      current_ = items_.get() + chunk * kChunk;
      return;
    }
    if (threaded_) {
      // Chunks before |chunk| are claimed, so next_chunk_ >= chunk: equal
      // means the thread has not claimed this one, so it will not.
      int expected = chunk;
      next_chunk_.compare_exchange_strong(expected, chunk + 1);
    }
    ComputeChunk(chunk, own_chunk_.get());
    current_ = own_chunk_.get();
  }

  const int n_;
  const int num_chunks_;
  const bool threaded_;
  const ComputeT compute_;
  // Default-initialised: memory untouched until computed.
  std::unique_ptr<T[]> own_chunk_;
  std::unique_ptr<T[]> items_;  // The thread's chunks.
  std::unique_ptr<std::atomic<uint8_t>[]> done_;
  std::atomic<int> next_chunk_{0};
  int current_chunk_ = -1;
  const T *current_ = nullptr;
  std::optional<SecondThread> worker_;
};

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_UV_LOOKAHEAD_H_
