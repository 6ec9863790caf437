/**
 * @fileoverview gltf-pipeline (4.x) with draco3d-uv: processGltf, processGlb,
 * gltfToGlb and glbToGltf as gltf-pipeline exports them, whose Draco stage
 * uses this package's encoder and decoder modules and codes texture
 * coordinates and tangents with draco-uv's coders chosen by
 * options.dracoOptions.texCoordCompression and tangentCompression:
 *
 *   const {gltfToGlb} = require('draco3d-uv/gltf-pipeline');
 *   const {glb} = await gltfToGlb(gltf, {dracoOptions: {
 *     compressionLevel: 7,
 *     texCoordCompression: {prediction: 'auto', seams: 'context'},
 *     tangentCompression: {prediction: 'auto'},
 *   }});
 *
 * (prediction, seams, anchors: draco_encoder's -uv_pred / -uv_seams /
 * -uv_anchors names; tangentCompression {prediction, quantizationBits}:
 * -tangent_pred's and -qtg, for TANGENT, which gltf-pipeline itself leaves
 * unquantized: with tangentCompression the tangents are quantized with
 * quantizationBits, by default 8 as in draco_transcoder; without these
 * options the coding is stock Draco 1.5.5's). When some primitive was encoded with draco-uv's ids, the
 * glTF gets DRACOUV_attribute_compression in extensionsUsed and
 * extensionsRequired (also with uncompressedFallback: loaders with a stock
 * Draco decoder would otherwise try the Draco data and fail). The stage's
 * encodes run between DracoUvModule.BeginGltfWrite() and EndGltfWrite(), so
 * that with prediction 'auto' the first primitive that would need the marker
 * keeps draco-uv's coding only if it saves more than the marker's JSON costs,
 * as in draco-uv's native glTF encoder.
 *
 * How: gltf-pipeline hard-codes require("draco3d") and creates its modules
 * once. This file loads a private copy of gltf-pipeline's own files (the
 * installed gltf-pipeline, a peer dependency) in which require("draco3d")
 * gives this package and the Draco stage is wrapped to set the encoder's
 * texture coordinate default and add the marker. The gltf-pipeline that
 * require('gltf-pipeline') gives is left untouched. Draco stages run one at a
 * time (the texture coordinate default is module-wide).
 */
'use strict';

const fs = require('fs');
const Module = require('module');
const path = require('path');
const draco3d = require('./draco3d.js');

const MARKER = 'DRACOUV_attribute_compression';

// Modules shared by all calls (gltf-pipeline also creates its modules once).
let encoderModulePromise;
let decoderModulePromise;
const shim = {
  createEncoderModule: () => encoderModulePromise ||
      (encoderModulePromise = draco3d.createEncoderModule({})),
  createDecoderModule: () => decoderModulePromise ||
      (decoderModulePromise = draco3d.createDecoderModule({})),
};

/**
 * Loads |filename| of the package in |packageDir| as a private module:
 * its relative requires of files of that package load private copies too,
 * |overrides| answers requires by name, everything else is required as
 * usual (shared).
 */
function loadPrivate(filename, packageDir, overrides, cache) {
  if (cache.has(filename)) {
    return cache.get(filename).exports;
  }
  const mod = new Module(filename, module);
  mod.filename = filename;
  mod.paths = Module._nodeModulePaths(path.dirname(filename));
  cache.set(filename, mod);
  mod.require = (request) => {
    if (Object.prototype.hasOwnProperty.call(overrides, request)) {
      return overrides[request];
    }
    if (request.startsWith('.')) {
      const resolved = Module._resolveFilename(request, mod);
      if (resolved.startsWith(packageDir + path.sep) &&
          !resolved.includes(path.sep + 'node_modules' + path.sep,
                             packageDir.length)) {
        return loadPrivate(resolved, packageDir, overrides, cache);
      }
    }
    return Module.prototype.require.call(mod, request);
  };
  mod._compile(fs.readFileSync(filename, 'utf8'), filename);
  mod.loaded = true;
  return mod.exports;
}

function addMarker(gltf) {
  for (const key of ['extensionsUsed', 'extensionsRequired']) {
    gltf[key] = gltf[key] || [];
    if (!gltf[key].includes(MARKER)) {
      gltf[key].push(MARKER);
    }
  }
}

/**
 * gltf-pipeline's compressDracoMeshes, with texCoordCompression and
 * tangentCompression.
 */
function wrapDracoStage(compressDracoMeshes) {
  let queue = Promise.resolve();
  async function compressOne(gltf, options) {
    const encoderModule = await shim.createEncoderModule();
    if (typeof encoderModule.DracoUvModule !== 'function') {
      throw new Error('draco3d-uv: this build has no texture coordinate ' +
                      'encoder API (DracoUvModule)');
    }
    const uvModule = new encoderModule.DracoUvModule();
    try {
      const {texCoordCompression, tangentCompression} =
          options.dracoOptions || {};
      if (texCoordCompression || tangentCompression) {
        draco3d.setUvDefault(encoderModule, texCoordCompression,
                             tangentCompression);
      } else {
        uvModule.ClearDefault();
      }
      const before = uvModule.GetNumEncodesWithDracoUvIds();
      uvModule.BeginGltfWrite();
      const result = await compressDracoMeshes(gltf, options);
      if (uvModule.GetNumEncodesWithDracoUvIds() > before) {
        addMarker(gltf);
      }
      return result;
    } finally {
      uvModule.EndGltfWrite();
      uvModule.ClearDefault();
      encoderModule.destroy(uvModule);
    }
  }
  function stage(gltf, options) {
    const run = queue.then(() => compressOne(gltf, options));
    queue = run.catch(() => {});
    return run;
  }
  stage.defaults = compressDracoMeshes.defaults;
  return stage;
}

let pipeline;

function loadPipeline() {
  if (pipeline) {
    return pipeline;
  }
  const index = require.resolve('gltf-pipeline');
  const packageDir = path.dirname(index);
  const cache = new Map();
  const overrides = {draco3d: shim};
  const compressFile = path.join(packageDir, 'lib', 'compressDracoMeshes.js');
  const stage = wrapDracoStage(
      loadPrivate(compressFile, packageDir, overrides, cache));
  // Relative requires of the Draco stage resolve to the wrapped stage.
  const wrapped = new Module(compressFile, module);
  wrapped.exports = stage;
  wrapped.loaded = true;
  cache.set(compressFile, wrapped);
  pipeline = loadPrivate(index, packageDir, overrides, cache);
  return pipeline;
}

module.exports = {
  get processGltf() {
    return loadPipeline().processGltf;
  },
  get processGlb() {
    return loadPipeline().processGlb;
  },
  get gltfToGlb() {
    return loadPipeline().gltfToGlb;
  },
  get glbToGltf() {
    return loadPipeline().glbToGltf;
  },
  DRACOUV_ATTRIBUTE_COMPRESSION: MARKER,
};
