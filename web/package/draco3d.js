/**
 * @fileoverview Main file of the draco3d-uv package: npm draco3d's entry
 * points, createDecoderModule and createEncoderModule, for Draco 1.5.5 with
 * draco-uv's texture coordinate coders (same JS API as draco3d's), plus
 * createUvOptions and createEncoderModule's texCoordCompression option, which
 * choose those coders by draco_encoder's flag names (README.md, "Encoding
 * with draco-uv's coders").
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

/**
 * A DracoUvOptions of |encoderModule| for the settings {prediction, seams,
 * anchors, rmse, texels, textureSize} (draco_encoder's -uv_pred, -uv_seams,
 * -uv_anchors, -uv_rmse, -uv_texels and -uv_texture_size values; an absent
 * or empty one keeps Draco's own, textureSize defaults to 4096). The caller
 * destroys it with encoderModule.destroy(). Throws an Error naming the valid
 * values when a value is unknown or an error target is not positive.
 */
function createUvOptions(encoderModule, settings) {
  const options = new encoderModule.DracoUvOptions();
  const setters = [
    ['prediction', 'SetPrediction'],
    ['seams', 'SetSeams'],
    ['anchors', 'SetAnchors'],
  ];
  for (const [key, setter] of setters) {
    const value = settings && settings[key];
    if (value === undefined || value === null || value === '') {
      continue;
    }
    if (!options[setter](String(value))) {
      fail(encoderModule, options, key);
    }
  }
  const has = (key) => settings && settings[key] !== undefined &&
      settings[key] !== null && settings[key] !== '';
  if (has('rmse') && !options.SetRmse(Number(settings.rmse))) {
    fail(encoderModule, options, 'rmse');
  }
  if (has('texels') &&
      !options.SetTexels(Number(settings.texels),
                         has('textureSize') ? Number(settings.textureSize) :
                                              4096)) {
    fail(encoderModule, options, 'texels');
  }
  return options;
}

/** Destroys |options| and throws the error of its last failing setter. */
function fail(encoderModule, options, key) {
  const message = options.GetErrorMessage();
  encoderModule.destroy(options);
  throw new Error(`texCoordCompression.${key}: ${message}`);
}

/**
 * Makes |settings| the module-wide default of |encoderModule|: every
 * TEX_COORD attribute without a setting of its own is coded with them.
 * Throws an Error for unknown or inconsistent values.
 */
function setUvDefault(encoderModule, settings) {
  const options = createUvOptions(encoderModule, settings);
  const uvModule = new encoderModule.DracoUvModule();
  const ok = uvModule.SetDefault(options);
  const message = uvModule.GetErrorMessage();
  encoderModule.destroy(uvModule);
  encoderModule.destroy(options);
  if (!ok) {
    throw new Error(`texCoordCompression: ${message}`);
  }
}

const createDecoderModule =
    createModuleFactory('./draco_wasm_wrapper.js', 'draco_decoder.wasm');
const createStockEncoderModule =
    createModuleFactory('./draco_encoder_wrapper.js', 'draco_encoder.wasm');

/**
 * draco3d's createEncoderModule. With options.texCoordCompression
 * ({prediction, seams, anchors, rmse, texels, textureSize}), the module's
 * default coding of texture
 * coordinates is set before the promise resolves; the promise is rejected
 * with an Error naming the valid values when a value is unknown.
 */
function createEncoderModule(options) {
  const moduleOptions = Object.assign({}, options);
  const texCoordCompression = moduleOptions.texCoordCompression;
  delete moduleOptions.texCoordCompression;
  const ready = createStockEncoderModule(moduleOptions);
  if (texCoordCompression === undefined) {
    return ready;
  }
  return ready.then((encoderModule) => {
    setUvDefault(encoderModule, texCoordCompression);
    return encoderModule;
  });
}

module.exports = {
  createEncoderModule,
  createDecoderModule,
  createUvOptions,
  setUvDefault,
};
