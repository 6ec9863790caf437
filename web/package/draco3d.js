/**
 * @fileoverview Main file of the draco3d-uv package: npm draco3d's entry
 * points, createDecoderModule and createEncoderModule, for Draco 1.5.5 with
 * draco-uv's texture coordinate and tangent coders (same JS API as
 * draco3d's), plus createUvOptions and createEncoderModule's
 * texCoordCompression and tangentCompression options, which choose those
 * coders by draco_encoder's flag names (README.md, "Encoding with draco-uv's
 * coders").
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

/** True when |settings| has a value for |key| (not absent, null or ''). */
function has(settings, key) {
  return Boolean(settings) && settings[key] !== undefined &&
      settings[key] !== null && settings[key] !== '';
}

/**
 * A DracoUvOptions of |encoderModule| for the texture coordinate settings
 * {prediction, seams, anchors, rmse, texels, textureSize} (draco_encoder's
 * -uv_pred, -uv_seams, -uv_anchors, -uv_rmse, -uv_texels and
 * -uv_texture_size values; an absent or empty one keeps Draco's own,
 * textureSize defaults to 4096) and the tangent settings
 * {prediction, quantizationBits} (-tangent_pred and -qtg: the prediction of
 * the mesh's tangents, GENERIC attributes with tangent values as
 * glTF-Transform and gltf-pipeline write glTF's TANGENT, and their bits
 * where nothing else quantizes them). The caller destroys it with
 * encoderModule.destroy(). Throws an Error naming the valid values when a
 * value is unknown or out of range.
 */
function createUvOptions(encoderModule, settings, tangentSettings) {
  const options = new encoderModule.DracoUvOptions();
  const setters = [
    ['texCoordCompression', settings, 'prediction', 'SetPrediction'],
    ['texCoordCompression', settings, 'seams', 'SetSeams'],
    ['texCoordCompression', settings, 'anchors', 'SetAnchors'],
    ['tangentCompression', tangentSettings, 'prediction',
     'SetTangentPrediction'],
  ];
  for (const [group, values, key, setter] of setters) {
    if (has(values, key) && !options[setter](String(values[key]))) {
      fail(encoderModule, options, `${group}.${key}`);
    }
  }
  if (has(settings, 'rmse') && !options.SetRmse(Number(settings.rmse))) {
    fail(encoderModule, options, 'texCoordCompression.rmse');
  }
  if (has(settings, 'texels') &&
      !options.SetTexels(Number(settings.texels),
                         has(settings, 'textureSize') ?
                             Number(settings.textureSize) :
                             4096)) {
    fail(encoderModule, options, 'texCoordCompression.texels');
  }
  // A whole number of bits (0: -tangent_pred's default):
  // SetTangentQuantization() takes a long, which would truncate 8.5 to 8.
  if (has(tangentSettings, 'quantizationBits')) {
    const bits = Number(tangentSettings.quantizationBits);
    if (!Number.isInteger(bits)) {
      encoderModule.destroy(options);
      throw new Error('tangentCompression.quantizationBits: -qtg needs a ' +
                      `whole number of bits, got '${
                          tangentSettings.quantizationBits}'.`);
    }
    if (!options.SetTangentQuantization(bits)) {
      fail(encoderModule, options, 'tangentCompression.quantizationBits');
    }
  }
  return options;
}

/** Destroys |options| and throws the error of its last failing setter. */
function fail(encoderModule, options, key) {
  const message = options.GetErrorMessage();
  encoderModule.destroy(options);
  throw new Error(`${key}: ${message}`);
}

/**
 * Makes |settings| (texture coordinates) and |tangentSettings| (tangents;
 * createUvOptions) the module-wide default of |encoderModule|: every mesh
 * encode without a setting of its own codes its TEX_COORD attributes, and
 * the tangents that follow them, with them. Throws an Error for unknown or
 * inconsistent values.
 */
function setUvDefault(encoderModule, settings, tangentSettings) {
  const options = createUvOptions(encoderModule, settings, tangentSettings);
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
 * ({prediction, seams, anchors, rmse, texels, textureSize}) and/or
 * options.tangentCompression ({prediction, quantizationBits}), the module's
 * default coding of texture coordinates and tangents is set before the
 * promise resolves; the promise is rejected with an Error naming the valid
 * values when a value is unknown.
 */
function createEncoderModule(options) {
  const moduleOptions = Object.assign({}, options);
  const {texCoordCompression, tangentCompression} = moduleOptions;
  delete moduleOptions.texCoordCompression;
  delete moduleOptions.tangentCompression;
  const ready = createStockEncoderModule(moduleOptions);
  if (texCoordCompression === undefined && tangentCompression === undefined) {
    return ready;
  }
  return ready.then((encoderModule) => {
    setUvDefault(encoderModule, texCoordCompression, tangentCompression);
    return encoderModule;
  });
}

module.exports = {
  createEncoderModule,
  createDecoderModule,
  createUvOptions,
  setUvDefault,
};
