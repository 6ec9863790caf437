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
// draco-uv's part of Draco's JavaScript encoder API (patches/0013): the
// IDL's DracoUvOptions and DracoUvModule interfaces, named at global scope
// as Emscripten's WebIDL binder's glue names them, and UvWebEncoder, which
// the wrapper's Encoder and ExpertEncoder hold and encode through.
#ifndef DRACO_EXT_HOOKS_WEB_ENCODER_H_
#define DRACO_EXT_HOOKS_WEB_ENCODER_H_

#include "draco_ext/web/uv_web_encoder.h"  // IWYU pragma: export

typedef draco::DracoUvOptions DracoUvOptions;
typedef draco::DracoUvModule DracoUvModule;

#endif  // DRACO_EXT_HOOKS_WEB_ENCODER_H_
