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
// A one-line fingerprint of what a Draco file decodes to, for pinning golden
// bitstreams and for comparing decoders built with different compilers and
// flags (scripts/make-golden.sh, scripts/check-determinism.sh).
#ifndef DRACO_EXT_EVAL_UV_DECODED_DIGEST_H_
#define DRACO_EXT_EVAL_UV_DECODED_DIGEST_H_

#include <cstddef>
#include <cstdint>
#include <string>

#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"

namespace draco {

// FNV-1a (64 bit) of |size| bytes, continuing from |hash|.
uint64_t Fnv1a64(const void *data, size_t size,
                 uint64_t hash = 0xcbf29ce484222325ull);

// "faces=F points=P" followed, per attribute in id order, by
// " TYPE:DATATYPExN=HASH", HASH being the FNV-1a of the attribute's values
// (native bytes) at every face corner in face order. Two meshes with the same
// digest have the same faces and the same values at every corner. |mesh|
// must pass CheckMeshIndices().
std::string MeshDigest(const Mesh &mesh);

// Error unless every face corner is one of the mesh's points and every
// point maps to a value of every attribute. Stock Draco's sequential
// connectivity decoder (1.5.5 and upstream) accepts face indices beyond the
// number of points (benchmarks/hostile.md), and reading such a mesh's values
// would read out of bounds.
Status CheckMeshIndices(const Mesh &mesh);

// Decodes the Draco mesh in |data|, checks it with CheckMeshIndices() and
// returns its MeshDigest(). With
// |quantized|, attribute transforms are skipped, so the digest covers the
// integers the bitstream codes (quantized positions and texture coordinates,
// octahedral normals) and no floating point arithmetic of the decoder.
StatusOr<std::string> DecodedMeshDigest(const char *data, size_t size,
                                        bool quantized);

}  // namespace draco

#endif  // DRACO_EXT_EVAL_UV_DECODED_DIGEST_H_
