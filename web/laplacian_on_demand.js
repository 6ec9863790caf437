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
// Post-js of the web decoder built with DRACO_UV_LAPLACIAN_ON_DEMAND: the
// lossy Laplacian coder's solver is a second WebAssembly module,
// draco_decoder_laplacian.wasm (draco_ext/web/uv_laplacian_part.cc), which
// this code loads the first time a file needs it, synchronously (the decode
// calls are synchronous): read from disk under Node.js, a synchronous
// XMLHttpRequest in a Web Worker. It finds the file, in this order, through
//   Module.dracoUvLaplacianWasm  its bytes (an ArrayBuffer or typed array),
//   Module.dracoUvPath           the folder that holds it (a string, so it
//                                survives postMessage: three.js's
//                                DRACOLoader.decoderConfig, which the
//                                package's GLTFLoader plugin sets),
//   Module.locateFile / the folder of this script, unless that is a blob:
//                                or data: URL (three.js and Babylon build
//                                their workers from a Blob),
//   dracoUvScriptUrl             the URL the script was loaded from, from a
//                                stack trace (web/laplacian_script_url.js;
//                                Babylon's workers load it with
//                                importScripts; three.js's evaluate its text
//                                from a Blob, so there it is unknown).
// On a browser's main thread it cannot load synchronously;
// Module.loadDracoUvLaplacian() loads it asynchronously beforehand (a
// Promise). One instance of the part serves the decodes (a fresh instance
// per decode would double their time: its memory is new and zeroed again);
// it is dropped, and its memory released, once it holds more than
// DRACO_UV_KEEP_BYTES after a decode or when it traps (at its memory cap). When the part is
// missing or fails, the decode fails and its status's error_msg() says why
// and what to do, instead of Draco's "Failed to decode point attributes.".
var DRACO_UV_PART = 'draco_decoder_laplacian.wasm';
var DRACO_UV_HOWTO = 'give the decoder module the absolute URL of its ' +
    'folder as option dracoUvPath (three.js: register draco3d-uv\'s ' +
    'GLTFLoader plugin, or set dracoLoader.decoderConfig.dracoUvPath)';
var DRACO_UV_KEEP_BYTES = 256 * 1024 * 1024;
var dracoUvPart = null;      // WebAssembly.Module of the part, once loaded
var dracoUvInstance = null;  // Its exports, between decodes
var dracoUvError = '';       // Why the last Laplacian decode could not run

function dracoUvPartUrl() {
  var folder = Module['dracoUvPath'];
  if (folder) return folder.replace(/\/?$/, '/') + DRACO_UV_PART;
  // emscripten leaves scriptDirectory empty in a worker run from a blob: URL.
  if (Module['locateFile'] || /^(?!blob:|data:)./.test(scriptDirectory)) {
    return locateFile(DRACO_UV_PART);
  }
  if (dracoUvScriptUrl) return dracoUvScriptUrl.replace(/[^/]*$/, DRACO_UV_PART);
  throw new Error('this decoder runs from a blob: or data: URL and cannot ' +
                  'tell where that file is: ' + DRACO_UV_HOWTO);
}

function dracoUvPartBytes() {
  var bytes = Module['dracoUvLaplacianWasm'];
  if (bytes) return bytes;
  var url = dracoUvPartUrl();
  if (ENVIRONMENT_IS_NODE) {
    return require('fs').readFileSync(/^file:/.test(url) ? new URL(url) : url);
  }
  if (!ENVIRONMENT_IS_WORKER) {
    throw new Error(DRACO_UV_PART + ' is needed for this file and cannot be ' +
                    'loaded synchronously on a page\'s main thread: decode ' +
                    'in a worker, or await decoderModule.' +
                    'loadDracoUvLaplacian() before decoding');
  }
  var request = new XMLHttpRequest();
  request.open('GET', url, false);
  request.responseType = 'arraybuffer';
  request.send(null);
  if (request.status && request.status != 200) {
    throw new Error(url + ': HTTP ' + request.status + '; ' + DRACO_UV_HOWTO);
  }
  return request.response;
}

Module['loadDracoUvLaplacian'] = function() {
  if (dracoUvPart) return Promise.resolve();
  return new Promise(function(resolve) {
    resolve(ENVIRONMENT_IS_NODE || Module['dracoUvLaplacianWasm'] ?
                dracoUvPartBytes() :
                fetch(dracoUvPartUrl()).then(function(response) {
                  if (!response.ok) {
                    throw new Error(response.url + ': HTTP ' + response.status);
                  }
                  return response.arrayBuffer();
                }));
  }).then(WebAssembly.compile).then(function(part) { dracoUvPart = part; });
};

// A fresh, initialised instance of the part (a WASI reactor). Of what it
// imports, memory growth notices are ignored; anything else it calls (its
// abort) is an error.
function dracoUvInstantiate() {
  var imports = {};
  WebAssembly.Module.imports(dracoUvPart).forEach(function(entry) {
    imports[entry.module] = imports[entry.module] || {};
    imports[entry.module][entry.name] = function() {
      if (entry.name != 'emscripten_notify_memory_growth') {
        throw new Error(DRACO_UV_PART + ' called ' + entry.name);
      }
    };
  });
  var part = new WebAssembly.Instance(dracoUvPart, imports).exports;
  part['_initialize']();
  return part;
}

// Called by DecodeUvLaplacianValues() (uv_laplacian_on_demand.cc) with
// pointers into this module's memory; returns the frame bits or -1.
function dracoUvDecodeLaplacian(positions, numVertices, faces, numFaces,
                                stream, size, version, uv) {
  try {
    dracoUvPart = dracoUvPart || new WebAssembly.Module(dracoUvPartBytes());
    var part = dracoUvInstance = dracoUvInstance || dracoUvInstantiate();
    var inputs = [[HEAPF64, positions >> 3, 3 * numVertices, Float64Array],
                  [HEAP32, faces >> 2, 3 * numFaces, Int32Array],
                  [HEAPU8, stream, size, Uint8Array]];
    var at = inputs.map(function(input) {
      var ptr = part['malloc'](input[2] * input[3].BYTES_PER_ELEMENT || 1);
      if (!ptr) throw new Error(DRACO_UV_PART + ' is out of memory');
      return ptr;
    });
    var out = part['malloc'](16 * numVertices || 1);
    if (!out) throw new Error(DRACO_UV_PART + ' is out of memory');
    inputs.forEach(function(input, i) {
      new input[3](part['memory'].buffer, at[i], input[2])
          .set(input[0].subarray(input[1], input[1] + input[2]));
    });
    var bits = part['draco_uv_laplacian_decode'](
        at[0], numVertices, at[1], numFaces, at[2], size, version, out);
    if (bits >= 0) {
      HEAPF64.set(new Float64Array(part['memory'].buffer, out, 2 * numVertices),
                  uv >> 3);
    }
    at.concat(out).forEach(part['free']);
    if (part['memory'].buffer.byteLength > DRACO_UV_KEEP_BYTES) {
      dracoUvInstance = null;
    }
    return bits;
  } catch (error) {
    dracoUvInstance = null;
    dracoUvError = 'draco-uv: ' + (dracoUvPart ? error.message :
        'this file needs ' + DRACO_UV_PART + ': ' + error.message +
        (/dracoUvPath|loadDracoUvLaplacian/.test(error.message) ? '' :
             '; ' + DRACO_UV_HOWTO));
    return -1;
  }
}

// The decoder's status says why a Laplacian decode could not run.
(function() {
  var decoder = Module['Decoder'].prototype;
  var errorMessage = Module['Status'].prototype['error_msg'];
  Module['Status'].prototype['error_msg'] = function() {
    return this.dracoUvError || errorMessage.call(this);
  };
  ['DecodeArrayToMesh', 'DecodeBufferToMesh'].forEach(function(name) {
    var decode = decoder[name];
    decoder[name] = function() {
      dracoUvError = '';
      var status = decode.apply(this, arguments);
      status.dracoUvError = status.ok() ? '' : dracoUvError;
      return status;
    };
  });
})();
