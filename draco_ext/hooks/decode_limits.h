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
// The memory limit Draco's patched decoders apply to counts a file claims
// before its data can confirm them (patches/0014): the Edgebreaker decoder
// sizes its corner table for the claimed faces and vertices, and the
// sequential point cloud decoder every attribute for the claimed points.
// The data behind those counts is entropy coded, and Draco's rANS coder
// gives the only symbol of a stream probability 1, at no cost in bits, so
// no count is too large for any number of bytes; a 4 KB file claiming 2^26
// faces otherwise takes gigabytes before it fails (or, as a point cloud,
// "decodes" to 67 million points), and aborts a WebAssembly decoder at its
// memory cap. What a decoder refuses instead, by the least memory the counts
// need:
//   * up to 256 MB: nothing (a WebAssembly decoder's memory can grow that
//     far, and such files are no threat);
//   * above 256 MB: counts that would expand the bytes left in the buffer
//     more than 65,536-fold (real meshes reach about 60-fold, perfectly
//     regular flat grids 16,429-fold at 8.4 million faces,
//     benchmarks/hostile.md, "Claimed counts");
//   * above 2 GB with 32-bit pointers (WebAssembly, 32-bit processes):
//     everything, as such a decoder cannot hold it (emscripten builds, ours
//     and npm draco3d's, cap their memory at 2 GB).
#ifndef DRACO_EXT_HOOKS_DECODE_LIMITS_H_
#define DRACO_EXT_HOOKS_DECODE_LIMITS_H_

#include <cstdint>

namespace draco {

// Whether a decoder may allocate for counts that need at least
// |min_decoded_bytes| of memory with |remaining_encoded_bytes| of its input
// left to decode them from.
inline bool DecodedSizeWithinLimits(uint64_t min_decoded_bytes,
                                    int64_t remaining_encoded_bytes) {
  constexpr uint64_t kAlwaysAllowedBytes = uint64_t{1} << 28;
  constexpr uint64_t kMaxExpansion = uint64_t{1} << 16;
  constexpr uint64_t kMaxBytesWith32BitPointers = uint64_t{1} << 31;
  if (min_decoded_bytes <= kAlwaysAllowedBytes) {
    return true;
  }
  if (sizeof(void *) < sizeof(uint64_t) &&
      min_decoded_bytes > kMaxBytesWith32BitPointers) {
    return false;
  }
  return remaining_encoded_bytes > 0 &&
         min_decoded_bytes / kMaxExpansion <=
             static_cast<uint64_t>(remaining_encoded_bytes);
}

}  // namespace draco

#endif  // DRACO_EXT_HOOKS_DECODE_LIMITS_H_
