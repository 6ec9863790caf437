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
// Extern-pre-js of the web decoder built with DRACO_UV_LAPLACIAN_ON_DEMAND,
// run when the script is evaluated: the http(s) or file URL it was loaded
// from, read from a stack trace, or '' (e.g. when it runs from a blob: URL).
// A worker that loads the decoder with importScripts() (Babylon.js) has a
// blob: URL as its own location, so this is how the decoder finds its
// Laplacian part there (web/laplacian_on_demand.js).
var dracoUvScriptUrl = (function() {
  var match = /(?:^|[\s(@])((?:https?|file):\/\/[^\s)]+)/.exec(
      new Error().stack || '');
  return match ? match[1].replace(/(:\d+)+$/, '') : '';
})();
