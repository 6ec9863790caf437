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
// The threads of draco-uv's coders: the process-wide cap on them and
// SecondThread, through which every one of them is started and joined.
#ifndef DRACO_EXT_COMMON_THREADS_H_
#define DRACO_EXT_COMMON_THREADS_H_

#include <atomic>
#include <functional>
#include <thread>
#include <utility>

#if defined(__linux__)
#include <sched.h>
#endif

namespace draco {

namespace threads_internal {
inline std::atomic<int> &MaxThreadsSetting() {
  static std::atomic<int> max_threads{2};
  return max_threads;
}
}  // namespace threads_internal

// Process-wide thread setting of draco-uv's coders (default 2). With 1 they
// never start a thread, e.g. for applications that already decode many
// meshes in parallel; above 1 they may run work on other threads (the
// weighted schemes one, the Laplacian decoder at most two at a time).
// Output never depends on it. Read each time a coder decides whether to
// start a thread, so it may change at any time, from any thread.
inline void SetMaxThreads(int max_threads) {
  threads_internal::MaxThreadsSetting().store(max_threads);
}
inline int MaxThreads() { return threads_internal::MaxThreadsSetting().load(); }

// SetMaxThreads() under the name the README gives applications: in
// namespace draco it says that it caps draco-uv's threads, not Draco's.
inline void SetUvMaxThreads(int max_threads) { SetMaxThreads(max_threads); }

// Whether this build can start threads at all: not a WebAssembly build
// without threads, where std::thread aborts. Code that only runs on a second
// thread can be left out of such builds with `if constexpr`.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
constexpr bool kBuildHasThreads = false;
#else
constexpr bool kBuildHasThreads = true;
#endif

// True when a second thread can run alongside this one: allowed by
// SetMaxThreads(), more than one core this process may use (on Linux its
// CPU affinity, so that `taskset -c 0` gives one thread), and not a
// WebAssembly build without threads (where std::thread aborts).
inline bool SecondThreadAvailable() {
  if (MaxThreads() < 2) {
    return false;
  }
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  return false;
#elif defined(__linux__)
  cpu_set_t cpus;
  if (sched_getaffinity(0, sizeof(cpus), &cpus) == 0) {
    return CPU_COUNT(&cpus) > 1;
  }
  return std::thread::hardware_concurrency() > 1;
#else
  return std::thread::hardware_concurrency() > 1;
#endif
}

// Runs one task alongside the caller's own work: on a second thread when
// the caller wants one and SecondThreadAvailable(), otherwise on the
// calling thread, to the end, before the constructor returns. Join() (or
// the destructor) waits for the task.
//
//   SecondThread side([&] { FirstHalf(); }, use_thread);
//   SecondHalf();
//   side.Join();
//
// Weak where: on one thread the task runs before anything the caller does
// after the constructor, so a task that waits for the caller deadlocks
// there; code that must give the same result both ways (all of draco-uv's)
// must not depend on which thread, or in what interleaving, the task runs.
// A task must not throw. Every SecondThread starts a new thread (there is
// no pool), so callers keep it for large work.
class SecondThread {
 public:
  explicit SecondThread(std::function<void()> task, bool use_thread = true) {
    if (use_thread && SecondThreadAvailable()) {
      thread_ = std::thread(std::move(task));
    } else {
      task();
    }
  }
  ~SecondThread() { Join(); }

  SecondThread(const SecondThread &) = delete;
  SecondThread &operator=(const SecondThread &) = delete;

  // Waits until the task has ended; returns at once when it ran on the
  // calling thread or was already joined.
  void Join() {
    if (thread_.joinable()) {
      thread_.join();
    }
  }

 private:
  std::thread thread_;
};

}  // namespace draco

#endif  // DRACO_EXT_COMMON_THREADS_H_
