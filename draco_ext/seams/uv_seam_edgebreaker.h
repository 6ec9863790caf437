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
// How Draco's Edgebreaker reaches the crease-bit seam coder
// (uv_seam_coder.h): two connectivity methods, Draco's standard and valence
// Edgebreaker with context-modelled seams instead of Draco's per-attribute
// static bit streams. Patch 0006 adds their ids
// (MESH_EDGEBREAKER_{STANDARD,VALENCE}_CONTEXT_SEAMS_ENCODING) and calls the
// functions below from MeshEdgebreakerEncoder / MeshEdgebreakerDecoder.
//
// Bitstream: the connectivity is Draco's, byte for byte, except for the
// method id and the seams: the traversal data end with
// varint(n) and the n bytes of EncodeUvSeams() instead of Draco's seam
// streams. Draco 1.5.5 to 1.5.7 reject the unknown method id
// ("Failed to initialize the decoder"), so no stock decoder misreads it.
#ifndef DRACO_EXT_SEAMS_UV_SEAM_EDGEBREAKER_H_
#define DRACO_EXT_SEAMS_UV_SEAM_EDGEBREAKER_H_

#include <cstdint>
#include <memory>
#include <vector>

#include "draco/compression/mesh/mesh_edgebreaker_decoder_impl_interface.h"
#include "draco/compression/mesh/mesh_edgebreaker_encoder_impl_interface.h"
#include "draco/mesh/corner_table.h"
#include "draco_ext/seams/uv_seam_coder.h"

namespace draco {

bool IsUvSeamEdgebreakerMethod(int method);

// The implementations of the two methods; null for other ids.
std::unique_ptr<MeshEdgebreakerEncoderImplInterface>
CreateUvSeamEdgebreakerEncoderImpl(int method);
std::unique_ptr<MeshEdgebreakerDecoderImplInterface>
CreateUvSeamEdgebreakerDecoderImpl(int method);

// The encoder's |table| renumbered to the decoder's corners: face f of the
// decoder has the corners |face_corners|[f], Next() and Previous() of it
// (MeshEdgebreakerEncoderImpl's processed connectivity corners). False if
// an opposite corner lies outside those faces.
bool CornerTableInDecoderOrder(const CornerTable &table,
                               const std::vector<CornerIndex> &face_corners,
                               UvSeamCornerTable *decoder_table);

// |table| as plain arrays.
UvSeamCornerTable UvSeamCornerTableOf(const CornerTable &table);

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_UV_SEAM_EDGEBREAKER_H_
