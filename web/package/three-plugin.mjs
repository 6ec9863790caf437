/**
 * three.js GLTFLoader plugin for glTF files written with draco-uv's coders.
 *
 * Such files list DRACOUV_attribute_compression in extensionsUsed and
 * extensionsRequired. The extension has no JSON object: it says that the
 * KHR_draco_mesh_compression buffers may use prediction or Edgebreaker ids
 * that only a draco-uv decoder knows. three.js decodes them once its
 * DRACOLoader points at this package's folder (setDecoderPath); this plugin
 * tells GLTFLoader that the extension is handled, so that it no longer
 * warns 'Unknown extension "DRACOUV_attribute_compression"', and tells the
 * DRACOLoader's workers where the decoder's Laplacian part
 * (draco_decoder_laplacian.wasm, loaded only for files whose texture
 * coordinates use the lossy Laplacian coder) is: the decoder folder, as an
 * absolute URL in decoderConfig.dracoUvPath, unless the page set one
 * (DRACOLoader builds its workers from a Blob, so they cannot find the
 * folder by themselves; without it such files fail with an error that says
 * so). It imports nothing (not even three), so a page can load it from the
 * package folder without an import map.
 *
 *   import {GLTFLoader} from 'three/addons/loaders/GLTFLoader.js';
 *   import {DRACOLoader} from 'three/addons/loaders/DRACOLoader.js';
 *   import {DracoUvAttributeCompressionPlugin} from 'draco3d-uv/three';
 *
 *   const dracoLoader = new DRACOLoader().setDecoderPath('/draco3d-uv/');
 *   const loader = new GLTFLoader().setDRACOLoader(dracoLoader);
 *   loader.register((parser) => new DracoUvAttributeCompressionPlugin(parser));
 */
'use strict';

/** The glTF extension name draco_transcoder writes. */
export const DRACOUV_ATTRIBUTE_COMPRESSION = 'DRACOUV_attribute_compression';

/** GLTFLoader plugin: marks DRACOUV_attribute_compression as supported. */
export class DracoUvAttributeCompressionPlugin {
  /** @param {object} parser three's GLTFParser (kept like three's plugins). */
  constructor(parser) {
    this.parser = parser;
    this.name = DRACOUV_ATTRIBUTE_COMPRESSION;
  }

  /** Before GLTFLoader loads anything: the Laplacian part's folder. */
  beforeRoot() {
    const draco = this.parser.extensions.KHR_draco_mesh_compression;
    const dracoLoader = draco && draco.dracoLoader;
    if (dracoLoader && dracoLoader.decoderConfig &&
        !dracoLoader.decoderConfig.dracoUvPath) {
      // The folder of draco_decoder.wasm (three r187's decoderPaths, or the
      // decoderPath of earlier releases); workers created from now on
      // receive it with the rest of the config.
      const wasm = dracoLoader.decoderPaths ? dracoLoader.decoderPaths.wasm :
          `${dracoLoader.decoderPath}draco_decoder.wasm`;
      const page = globalThis.location && globalThis.location.href;
      dracoLoader.decoderConfig.dracoUvPath =
          page ? new URL('.', new URL(wasm, page)).href :
                 wasm.replace(/[^/]*$/, '');
    }
    return null;
  }
}
