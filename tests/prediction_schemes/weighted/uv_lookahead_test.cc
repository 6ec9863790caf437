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
#include "prediction_schemes/weighted/uv_lookahead.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

#include "gtest/gtest.h"

namespace draco {
namespace {

uint64_t ItemValue(int i) {
  return (static_cast<uint64_t>(i) * 0x9e3779b97f4a7c15ull) ^ (i >> 3);
}

void ComputeItems(int begin, int end, uint64_t *out) {
  for (int i = begin; i < end; ++i) {
    *out++ = ItemValue(i);
  }
}

TEST(UvLookaheadTest, GivesEveryItemInOrderWithAndWithoutThread) {
  const int chunk = UvLookahead<uint64_t>::kChunk;
  for (const bool threaded : {false, true}) {
    for (const int n : {0, 1, chunk - 1, chunk, chunk + 1, 37 * chunk + 5}) {
      UvLookahead<uint64_t> items(n, threaded, ComputeItems);
      for (int i = 0; i < n; ++i) {
        ASSERT_EQ(items.Get(i), ItemValue(i))
            << "n " << n << " i " << i << " threaded " << threaded;
      }
    }
  }
}

// The consumer must never wait for the second thread: here the thread
// stalls in its first chunk until the consumer has read every item, which
// would deadlock a consumer that waits.
TEST(UvLookaheadTest, NeverWaitsForAStalledThread) {
  const std::thread::id consumer = std::this_thread::get_id();
  std::atomic<bool> consumed{false};
  std::atomic<bool> thread_started{false};
  const int n = 20 * UvLookahead<uint64_t>::kChunk;
  {
    UvLookahead<uint64_t> items(n, true,
                                [&](int begin, int end, uint64_t *out) {
                                  if (std::this_thread::get_id() != consumer) {
                                    thread_started = true;
                                    while (!consumed) {
                                      std::this_thread::yield();
                                    }
                                  }
                                  ComputeItems(begin, end, out);
                                });
    // If Get() waited for the stalled thread, the loop below would never
    // end; the watchdog then releases the thread, so the test fails instead
    // of hanging.
    std::mutex mutex;
    std::condition_variable done_signal;
    bool done = false;
    bool watchdog_fired = false;
    std::thread watchdog([&] {
      std::unique_lock<std::mutex> lock(mutex);
      if (!done_signal.wait_for(lock, std::chrono::seconds(60),
                                [&] { return done; })) {
        watchdog_fired = true;
        consumed = true;
      }
    });
    // Let the thread claim a chunk (if it runs at all) before consuming.
    for (int spins = 0; spins < 1000000 && !thread_started; ++spins) {
      std::this_thread::yield();
    }
    bool values_match = true;
    for (int i = 0; i < n && values_match; ++i) {
      values_match = items.Get(i) == ItemValue(i);
      EXPECT_TRUE(values_match) << i;
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      done = true;
      EXPECT_FALSE(watchdog_fired)
          << "Get() waited 60 s for a stalled lookahead thread";
    }
    done_signal.notify_one();
    watchdog.join();
    consumed = true;
  }
}

}  // namespace
}  // namespace draco
