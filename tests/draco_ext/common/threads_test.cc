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
#include "draco_ext/common/threads.h"

#include <atomic>
#include <chrono>
#include <thread>

#include "gtest/gtest.h"

namespace draco {
namespace {

// Sets the process-wide cap for one test and restores it after.
class ScopedMaxThreads {
 public:
  explicit ScopedMaxThreads(int max_threads) : saved_(MaxThreads()) {
    SetMaxThreads(max_threads);
  }
  ~ScopedMaxThreads() { SetMaxThreads(saved_); }

 private:
  const int saved_;
};

TEST(ThreadsTest, MaxThreadsOfOneAllowsNoSecondThread) {
  ScopedMaxThreads cap(1);
  EXPECT_FALSE(SecondThreadAvailable());
}

TEST(ThreadsTest, SetUvMaxThreadsIsSetMaxThreads) {
  ScopedMaxThreads cap(2);
  SetUvMaxThreads(1);
  EXPECT_EQ(MaxThreads(), 1);
  EXPECT_FALSE(SecondThreadAvailable());
}

// Without a second thread the task has ended when the constructor returns,
// on the calling thread.
TEST(ThreadsTest, SecondThreadRunsTheTaskHereWhenNoThreadIsWanted) {
  const std::thread::id caller = std::this_thread::get_id();
  for (const bool capped : {false, true}) {
    ScopedMaxThreads cap(capped ? 1 : 2);
    std::thread::id runner;
    // Capped, a thread is wanted but not allowed.
    SecondThread side([&] { runner = std::this_thread::get_id(); }, capped);
    EXPECT_EQ(runner, caller) << "capped " << capped;
    side.Join();
    side.Join();
  }
}

// With a second thread the task runs alongside the caller: here it waits
// for the caller to go on, which would deadlock on one thread (a 60 s
// bound turns that into a failure).
TEST(ThreadsTest, SecondThreadRunsAlongsideTheCallerWhenAvailable) {
  ScopedMaxThreads cap(2);
  if (!SecondThreadAvailable()) {
    GTEST_SKIP() << "one CPU";
  }
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> caller_went_on{false};
  bool saw_caller = false;
  std::thread::id runner;
  {
    SecondThread side([&] {
      runner = std::this_thread::get_id();
      const auto deadline =
          std::chrono::steady_clock::now() + std::chrono::seconds(60);
      while (!caller_went_on && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::yield();
      }
      saw_caller = caller_went_on;
    });
    caller_went_on = true;
  }  // The destructor joins.
  EXPECT_TRUE(saw_caller);
  EXPECT_NE(runner, caller);
}

}  // namespace
}  // namespace draco
