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
// The 8 bytes that start the prediction data of every draco-uv prediction
// scheme, so that decoders without draco-uv fail instead of decoding wrong
// texture coordinates.
//
// Draco 1.5.5 does not reject an unknown prediction scheme id: it decodes the
// attribute with delta prediction and the wrap transform, whose prediction
// data are two int32 bounds (min, max) it rejects when min > max. The guard
// is exactly such a pair: "DUV1" (0x31565544) followed by -1, so a stock
// 1.5.5 decoder stops with "Failed to decode point attributes". Draco 1.5.7
// and newer reject the unknown id before reading anything.
#ifndef DRACO_EXT_COMMON_UV_BITSTREAM_GUARD_H_
#define DRACO_EXT_COMMON_UV_BITSTREAM_GUARD_H_

#include <cstdint>

#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"

namespace draco {

constexpr int32_t kUvGuardFirst = 0x31565544;  // "DUV1" little-endian.
constexpr int32_t kUvGuardSecond = -1;         // Below the first: min > max.

inline void EncodeUvBitstreamGuard(EncoderBuffer *buffer) {
  buffer->Encode(kUvGuardFirst);
  buffer->Encode(kUvGuardSecond);
}

// Reads the guard; false when it is missing or altered.
inline bool DecodeUvBitstreamGuard(DecoderBuffer *buffer) {
  int32_t first, second;
  return buffer->Decode(&first) && buffer->Decode(&second) &&
         first == kUvGuardFirst && second == kUvGuardSecond;
}

}  // namespace draco

#endif  // DRACO_EXT_COMMON_UV_BITSTREAM_GUARD_H_
