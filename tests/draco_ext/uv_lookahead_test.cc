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
#include "draco_ext/uv_lookahead.h"

#include <atomic>
#include <cstdint>
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
    // Let the thread claim a chunk (if it runs at all) before consuming.
    for (int spins = 0; spins < 1000000 && !thread_started; ++spins) {
      std::this_thread::yield();
    }
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(items.Get(i), ItemValue(i)) << i;
    }
    consumed = true;
  }
}

TEST(UvLookaheadTest, MaxThreadsOfOneAllowsNoSecondThread) {
  const int saved = UvMaxThreads();
  SetUvMaxThreads(1);
  EXPECT_FALSE(UvSecondThreadAvailable());
  SetUvMaxThreads(saved);
}

}  // namespace
}  // namespace draco
