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
// What Draco's JavaScript encoder API (draco_web_encoder.idl, patches/0013)
// adds for draco-uv's texture-coordinate and tangent coders:
//   DracoUvOptions  one TEX_COORD attribute's coding, by draco_encoder's
//                   flag names (-uv_pred, -uv_seams, -uv_anchors, -uv_rmse,
//                   -uv_texels), and that of the mesh's tangents which
//                   follow it (-tangent_pred, -qtg);
//   DracoUvModule   the module-wide default for every TEX_COORD attribute
//                   without a setting of its own, a count of the encodes
//                   that wrote draco-uv ids, and the glTF writes under way
//                   (in which -uv_pred and -tangent_pred auto pay for the
//                   glTF extension as in the native glTF encoder,
//                   gltf/uv_gltf.h);
//   UvWebEncoder    the part of the JS Encoder and ExpertEncoder that holds
//                   their per-attribute settings and encodes: stock Draco's
//                   own path when no setting applies (byte-identical
//                   output), else an ExpertEncoder made from the same options
//                   as draco::Encoder makes it, configured by
//                   ConfigureUvCompression() like draco_encoder's.
// Plain C++ without Emscripten, so it is unit-tested natively.
#ifndef DRACO_EXT_WEB_UV_WEB_ENCODER_H_
#define DRACO_EXT_WEB_UV_WEB_ENCODER_H_

#include <map>
#include <optional>
#include <string>

#include "draco/attributes/geometry_attribute.h"
#include "draco/compression/encode.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/encoder_buffer.h"
#include "draco/core/status.h"
#include "draco/mesh/mesh.h"
#include "draco/point_cloud/point_cloud.h"
#include "draco_ext/options/uv_compression_options.h"

namespace draco {

// IDL DracoUvOptions. The Set* calls may come in any order; whether the
// whole is consistent (anchors only with a Laplacian prediction) is checked
// where the options are applied (DracoUvModule::SetDefault(),
// UvWebEncoder::SetFor*()).
class DracoUvOptions {
 public:
  DracoUvOptions() = default;

  // A -uv_pred name; "" is Draco's own prediction.
  bool SetPrediction(const char *name);
  // A -uv_seams name; "" is Draco's own seam coding.
  bool SetSeams(const char *name);
  // A -uv_anchors value ("50", "2%", "random:50"); "" is the default.
  bool SetAnchors(const char *spec);
  // An error target: -uv_rmse |rmse| (UV units), or -uv_texels |texels|
  // -uv_texture_size |texture_size|; each replaces the other. Fails on
  // values that are not finite and positive. The WebAssembly build has no
  // decoder to measure the Laplacian coder with, so there the target
  // chooses among the lossless schemes only (options/uv_error_target.h).
  bool SetRmse(double rmse);
  bool SetTexels(double texels, long texture_size);
  // A -tangent_pred name for the mesh's tangents (TANGENT attributes, and
  // the GENERIC ones with tangent values, as glTF-Transform and
  // gltf-pipeline hand glTF's TANGENT to Draco: TangentAttributeIds());
  // "" is Draco's own prediction.
  bool SetTangentPrediction(const char *name);
  // -qtg: quantization bits of the tangents where the encoder does not
  // quantize them already; 0 leaves it to -tangent_pred's default (8 bits
  // for the geometric names).
  bool SetTangentQuantization(long bits);
  // Why the last failing Set* failed (listing the valid values), else "".
  const char *GetErrorMessage() const { return error_.c_str(); }

  const UvCompressionOptions &options() const { return options_; }

 private:
  bool Result(const Status &status);

  UvCompressionOptions options_;
  std::string error_;
};

// The module-wide state every encoder of one program shares (one per
// WebAssembly module instance).
class UvWebModuleState {
 public:
  static UvWebModuleState &Instance();

  // Fails, leaving the default as it was, when |options| are inconsistent.
  Status SetDefault(const UvCompressionOptions &options);
  void ClearDefault() { default_.reset(); }
  const std::optional<UvCompressionOptions> &default_options() const {
    return default_;
  }

  int num_encodes_with_draco_uv_ids() const {
    return num_encodes_with_draco_uv_ids_;
  }
  // Counts an encode that wrote draco-uv ids; in a glTF write, the file now
  // carries the glTF extension.
  void CountEncodeWithDracoUvIds();

  // A glTF writer's encodes (KHR_draco_mesh_compression primitives of one
  // file) begin: until one of them writes draco-uv ids, the file does not
  // carry kUvGltfExtension, so the schemes -uv_pred auto and -tangent_pred
  // auto choose are kept only if they pay for it
  // (KeepDracoUvOnlyIfItPaysForTheExtension()). A second Begin starts a new
  // file.
  void BeginGltfWrite() { gltf_write_ = GltfWrite::kExtensionNotYetPaid; }
  void EndGltfWrite() { gltf_write_ = GltfWrite::kNone; }
  // True in a glTF write whose encodes have not written draco-uv ids yet.
  bool gltf_extension_not_yet_paid() const {
    return gltf_write_ == GltfWrite::kExtensionNotYetPaid;
  }

 private:
  enum class GltfWrite { kNone, kExtensionNotYetPaid, kExtensionPaid };

  std::optional<UvCompressionOptions> default_;
  int num_encodes_with_draco_uv_ids_ = 0;
  GltfWrite gltf_write_ = GltfWrite::kNone;
};

// IDL DracoUvModule: a handle on a UvWebModuleState, by default the
// program's.
class DracoUvModule {
 public:
  DracoUvModule() : DracoUvModule(&UvWebModuleState::Instance()) {}
  explicit DracoUvModule(UvWebModuleState *state) : state_(state) {}

  // False + GetErrorMessage() when |options| is null or inconsistent.
  bool SetDefault(const DracoUvOptions *options);
  void ClearDefault() { state_->ClearDefault(); }
  long GetNumEncodesWithDracoUvIds() const {
    return state_->num_encodes_with_draco_uv_ids();
  }
  // Around the encodes of one glTF or GLB file (UvWebModuleState).
  void BeginGltfWrite() { state_->BeginGltfWrite(); }
  void EndGltfWrite() { state_->EndGltfWrite(); }
  const char *GetErrorMessage() const { return error_.c_str(); }

 private:
  UvWebModuleState *state_;
  std::string error_;
};

// The draco-uv state of one JS Encoder or ExpertEncoder.
class UvWebEncoder {
 public:
  UvWebEncoder() : UvWebEncoder(&UvWebModuleState::Instance()) {}
  explicit UvWebEncoder(UvWebModuleState *module) : module_(module) {}

  // Encoder.SetAttributeUvCompression: |options| for every TEX_COORD
  // attribute (|type| must be TEX_COORD), instead of the module default.
  bool SetForType(GeometryAttribute::Type type, const DracoUvOptions *options);
  // ExpertEncoder.SetAttributeUvCompression: |options| for attribute
  // |att_id| of |pc|, which must be a TEX_COORD attribute of a mesh.
  bool SetForAttribute(const PointCloud *pc, int att_id,
                       const DracoUvOptions *options);

  // Encoder.EncodeMeshToDracoBuffer's encode of |mesh| with |encoder|'s
  // options.
  Status EncodeMesh(const Mesh &mesh, Encoder *encoder, EncoderBuffer *out);
  // Encoder.EncodePointCloudToDracoBuffer: always stock Draco (point clouds
  // have no connectivity to predict texture coordinates from).
  Status EncodePointCloud(const PointCloud &pc, Encoder *encoder,
                          EncoderBuffer *out);
  // ExpertEncoder.EncodeToDracoBuffer: |pc| is the geometry |encoder| was
  // made for. |encoder|'s own options are left as the caller set them.
  Status EncodeWithExpert(const PointCloud &pc, ExpertEncoder *encoder,
                          EncoderBuffer *out);

  // The last encode succeeded and wrote draco-uv ids (a stock decoder
  // refuses its output).
  bool UsedDracoUvCoding() const { return used_draco_uv_coding_; }
  // The error of the last failing SetFor* or encode, else what the last
  // encode chose per attribute ("" when it was stock Draco's).
  const char *GetUvCompressionMessage() const { return message_.c_str(); }
  long num_encoded_points() const { return num_encoded_points_; }
  long num_encoded_faces() const { return num_encoded_faces_; }

 private:
  // The options of each TEX_COORD attribute of |mesh| that has any: its
  // own, else the per-type ones, else the module default. The tangent
  // options ride on them (ConfigureUvCompression()), so tangents are
  // predicted in meshes with texture coordinates, which the prediction
  // reads anyway.
  std::map<int, UvCompressionOptions> OptionsFor(const Mesh &mesh) const;
  // Configures a copy of |options| for |mesh| and encodes with it; in a
  // glTF write whose file does not carry the glTF extension yet, the
  // draco-uv ids that only auto chose are kept only if they pay for it.
  Status EncodeConfigured(const Mesh &mesh, const EncoderOptions &options,
                          EncoderBuffer *out);
  // Records the outcome of an encode and returns |status|.
  Status Finish(const Status &status, bool used_draco_uv_ids,
                const std::string &summary);
  bool Refuse(const std::string &message);

  UvWebModuleState *module_;
  std::optional<UvCompressionOptions> for_type_;
  std::map<int, UvCompressionOptions> for_attribute_;
  bool used_draco_uv_coding_ = false;
  std::string message_;
  long num_encoded_points_ = 0;
  long num_encoded_faces_ = 0;
};

}  // namespace draco

#endif  // DRACO_EXT_WEB_UV_WEB_ENCODER_H_
