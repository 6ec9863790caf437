/**
 * @fileoverview Main file of the draco3d-uv package: npm draco3d's entry
 * points, createDecoderModule and createEncoderModule, for Draco 1.5.5 with
 * draco-uv's texture coordinate coders (same JS API as draco3d's).
 *
 * The glue of the emscripten that builds this package (Debian's 3.1.6)
 * would fetch() its .wasm by file path under Node.js 18 and newer, which
 * fails; so in Node.js the .wasm is read from disk here and passed as
 * wasmBinary, unless the caller passes wasmBinary or instantiateWasm. A
 * caller's locateFile(name, folder) still chooses the file.
 */
'use strict';

function createModuleFactory(wrapper, wasmFile) {
  return function createModule(options) {
    const module = Object.assign({}, options);
    const isNode = typeof process === 'object' && process.versions &&
        process.versions.node;
    if (isNode && !module.wasmBinary && !module.instantiateWasm) {
      const fs = require('fs');
      const path = require('path');
      const file = module.locateFile ?
          module.locateFile(wasmFile, __dirname + path.sep) :
          path.join(__dirname, wasmFile);
      module.wasmBinary = fs.readFileSync(file);
    }
    return require(wrapper)(module);
  };
}

const createDecoderModule =
    createModuleFactory('./draco_wasm_wrapper.js', 'draco_decoder.wasm');
const createEncoderModule =
    createModuleFactory('./draco_encoder_wrapper.js', 'draco_encoder.wasm');

module.exports = {
  createEncoderModule,
  createDecoderModule,
};
