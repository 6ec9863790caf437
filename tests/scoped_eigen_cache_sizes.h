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
// Eigen's cache sizes as another CPU would report them, for tests of code
// whose results must not depend on them.
#ifndef DRACO_UV_TESTS_SCOPED_EIGEN_CACHE_SIZES_H_
#define DRACO_UV_TESTS_SCOPED_EIGEN_CACHE_SIZES_H_

#include <cstddef>

#include <Eigen/Core>

namespace draco {

// Sets the cache sizes by which Eigen blocks its matrix kernels for the
// object's lifetime. The defaults are those of a CPU with an L1 of 16 KB,
// with which Eigen rounds its products differently than with the usual
// 32 KB or more.
class ScopedEigenCacheSizes {
 public:
  ScopedEigenCacheSizes(std::ptrdiff_t l1 = 16 << 10,
                        std::ptrdiff_t l2 = 256 << 10,
                        std::ptrdiff_t l3 = 4 << 20)
      : l1_(Eigen::l1CacheSize()),
        l2_(Eigen::l2CacheSize()),
        l3_(Eigen::l3CacheSize()) {
    Eigen::setCpuCacheSizes(l1, l2, l3);
  }
  ~ScopedEigenCacheSizes() { Eigen::setCpuCacheSizes(l1_, l2_, l3_); }

  ScopedEigenCacheSizes(const ScopedEigenCacheSizes &) = delete;
  ScopedEigenCacheSizes &operator=(const ScopedEigenCacheSizes &) = delete;

 private:
  const std::ptrdiff_t l1_, l2_, l3_;
};

}  // namespace draco

#endif  // DRACO_UV_TESTS_SCOPED_EIGEN_CACHE_SIZES_H_
