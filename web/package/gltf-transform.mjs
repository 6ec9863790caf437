/**
 * @fileoverview glTF-Transform support for draco3d-uv: the Extension class of
 * DRACOUV_attribute_compression and registerDracoUv(), which sets up a
 * glTF-Transform I/O to read and write files with draco-uv's texture
 * coordinate and tangent coders.
 *
 * DRACOUV_attribute_compression has no JSON object of its own (like
 * KHR_mesh_quantization): listed in extensionsUsed and extensionsRequired,
 * it says that the Draco buffers of KHR_draco_mesh_compression may use
 * prediction scheme or Edgebreaker method ids that only a decoder with
 * draco-uv knows (draco_ext/gltf/uv_gltf_extension.h in draco-uv). So:
 *  - reading: registering the class lets glTF-Transform open files that
 *    require it; KHRDracoMeshCompression decodes them with whatever
 *    'draco3d.decoder' the I/O has, which must be this package's.
 *  - writing: the extension writes itself into extensionsUsed and
 *    extensionsRequired exactly when some primitive of this write was encoded
 *    with draco-uv's ids (the encoder module's
 *    DracoUvModule.GetNumEncodesWithDracoUvIds() grew during the write), and
 *    removes itself otherwise: a file that stock decoders can read never
 *    requires it, and one they cannot read always does. The write's encodes
 *    run between DracoUvModule.BeginGltfWrite() and EndGltfWrite(), so that
 *    with prediction 'auto' the first primitive that would need the marker
 *    keeps draco-uv's coding only if it saves more than the marker's JSON
 *    costs (76 bytes), as draco-uv's native glTF encoder does: auto (of
 *    texture coordinates or tangents) never makes a file bigger than stock
 *    coding.
 *
 * The extension must be present on a Document for its write hook to run:
 * registerDracoUv() adds it to every Document the I/O writes; without that
 * helper, call document.createExtension(DracoUvAttributeCompression) before
 * io.write().
 */
'use strict';

import {Extension} from '@gltf-transform/core';
import {KHRDracoMeshCompression} from '@gltf-transform/extensions';
import draco3d from './draco3d.js';

/** The extension's name, as draco-uv's native glTF encoder writes it. */
export const DRACOUV_ATTRIBUTE_COMPRESSION = 'DRACOUV_attribute_compression';

const ENCODER = 'draco3d.encoder';

// One DracoUvModule per encoder module (the handle to its module-wide state).
const uvModules = new WeakMap();

/**
 * The DracoUvModule of |encoderModule|, or null for a module without
 * draco-uv's encoder API (npm draco3d's).
 */
function uvModuleOf(encoderModule) {
  if (!encoderModule || typeof encoderModule.DracoUvModule !== 'function') {
    return null;
  }
  let uvModule = uvModules.get(encoderModule);
  if (!uvModule) {
    uvModule = new encoderModule.DracoUvModule();
    uvModules.set(encoderModule, uvModule);
  }
  return uvModule;
}

/**
 * Successful encodes so far in |encoderModule| that wrote draco-uv ids; 0 for
 * a module without draco-uv's encoder API (npm draco3d's), which cannot
 * write them.
 */
export function countDracoUvEncodes(encoderModule) {
  const uvModule = uvModuleOf(encoderModule);
  return uvModule ? uvModule.GetNumEncodesWithDracoUvIds() : 0;
}

/**
 * Tells |encoderModule| that the encodes of one glTF file begin (|begin|) or
 * end: in between, prediction 'auto' pays for the marker as in draco-uv's
 * native glTF encoder. No-op for modules without draco-uv's encoder API.
 */
function markGltfWrite(encoderModule, begin) {
  const uvModule = uvModuleOf(encoderModule);
  if (uvModule) {
    if (begin) {
      uvModule.BeginGltfWrite();
    } else {
      uvModule.EndGltfWrite();
    }
  }
}

/**
 * DRACOUV_attribute_compression: marks files whose Draco buffers use
 * draco-uv's coders. Register it next to KHRDracoMeshCompression.
 */
export class DracoUvAttributeCompression extends Extension {
  static EXTENSION_NAME = DRACOUV_ATTRIBUTE_COMPRESSION;
  extensionName = DRACOUV_ATTRIBUTE_COMPRESSION;
  writeDependencies = [ENCODER];

  // The encoder module of the write under way and its count of draco-uv
  // encodes when the write began (install() runs before any prewrite hook,
  // where KHRDracoMeshCompression encodes; write() after them).
  _encoderModule = null;
  _encodesBefore = 0;

  /** @hidden */
  install(key, dependency) {
    if (key === ENCODER) {
      this._encoderModule = dependency || null;
      this._encodesBefore = countDracoUvEncodes(this._encoderModule);
      markGltfWrite(this._encoderModule, true);
    }
    return this;
  }

  /** @hidden Nothing to read: the marker has no JSON object. */
  read(_context) {
    return this;
  }

  /** @hidden */
  write(context) {
    markGltfWrite(this._encoderModule, false);
    const json = context.jsonDoc.json;
    const name = this.extensionName;
    const used =
        countDracoUvEncodes(this._encoderModule) > this._encodesBefore;
    for (const key of ['extensionsUsed', 'extensionsRequired']) {
      const names = (json[key] || []).filter((entry) => entry !== name);
      json[key] = used ? [...names, name].sort() : names;
    }
    return this;
  }
}

/**
 * Sets up |io| (a NodeIO or WebIO) to read and write with draco3d-uv:
 * registers KHRDracoMeshCompression and DracoUvAttributeCompression, this
 * package's decoder and encoder modules as 'draco3d.decoder' and
 * 'draco3d.encoder', and adds DracoUvAttributeCompression to every Document
 * the I/O writes (for the duration of the write, so that it marks the file
 * when needed).
 *
 * @param {!Object} io a glTF-Transform PlatformIO.
 * @param {{texCoordCompression: (Object|undefined),
 *          tangentCompression: (Object|undefined),
 *          decoderModule: (Object|undefined),
 *          encoderModule: (Object|undefined)}=} options
 *     texCoordCompression: {prediction, seams, anchors} by draco_encoder's
 *     -uv_pred / -uv_seams / -uv_anchors names, the coding of every
 *     TEXCOORD_n this I/O writes (default: none, stock Draco coding);
 *     tangentCompression: {prediction, quantizationBits} by -tangent_pred
 *     and -qtg, the coding of every TANGENT this I/O writes, predicted from
 *     the primitive's first TEX_COORD attribute (default: none, stock
 *     Draco coding; draco()'s quantizeGeneric, 12 bits by default,
 *     quantizes the tangents, so quantizationBits applies only with
 *     quantizeGeneric 0);
 *     decoderModule / encoderModule: modules to use instead of new ones.
 * @return {!Promise<!Object>} |io|; rejects with the encoder's message when
 *     a name in texCoordCompression or tangentCompression is unknown.
 */
export async function registerDracoUv(io, options = {}) {
  const [decoderModule, encoderModule] = await Promise.all([
    options.decoderModule || draco3d.createDecoderModule({}),
    options.encoderModule ||
        draco3d.createEncoderModule({
          texCoordCompression: options.texCoordCompression,
          tangentCompression: options.tangentCompression,
        }),
  ]);
  io.registerExtensions([KHRDracoMeshCompression, DracoUvAttributeCompression])
      .registerDependencies({
        'draco3d.decoder': decoderModule,
        [ENCODER]: encoderModule,
      });
  // writeBinary() and NodeIO.write() both write through writeJSON().
  const writeJSON = io.writeJSON.bind(io);
  io.writeJSON = async (document, writerOptions) => {
    const root = document.getRoot();
    const present = root.listExtensionsUsed().some(
        (ext) => ext.extensionName === DRACOUV_ATTRIBUTE_COMPRESSION);
    const added =
        present ? null : document.createExtension(DracoUvAttributeCompression);
    try {
      return await writeJSON(document, writerOptions);
    } finally {
      // Also when the write failed between the extension's install() and
      // write().
      markGltfWrite(encoderModule, false);
      if (added) {
        added.dispose();
      }
    }
  };
  return io;
}
