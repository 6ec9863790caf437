/**
 * @fileoverview Config file for the gltf-transform CLI (@gltf-transform/cli
 * 4's --config) that reads and writes Draco with draco3d-uv:
 *
 *   gltf-transform draco in.glb out.glb \
 *       --config node_modules/draco3d-uv/gltf-transform.config.mjs
 *
 * writes every TEXCOORD_n and TANGENT with draco-uv's coders and marks the
 * file with DRACOUV_attribute_compression when some primitive used them; any
 * command given this config also reads such files. The coders are chosen by
 * draco_encoder's -uv_pred / -uv_seams / -uv_anchors / -tangent_pred names
 * in environment variables:
 *
 *   DRACO_UV_PRED       prediction (default "auto"; "draco" = stock Draco's)
 *   DRACO_UV_SEAMS      seam coding (default "context"; "draco" = stock's)
 *   DRACO_UV_ANCHORS    Laplacian anchors, e.g. "2%" (default: the scheme's)
 *   DRACO_TANGENT_PRED  tangent prediction (default "auto": draco-uv's
 *                       geometric prediction where it is smaller, and pays
 *                       for the marker, else stock; "draco" = stock's)
 *
 * An unknown name stops the CLI with the list of valid names. The config
 * keeps the CLI's other extensions and dependencies (meshopt, ...): it only
 * adds to the CLI's I/O (onProgramReady).
 */
'use strict';

import {registerDracoUv} from './gltf-transform.mjs';

function texCoordCompressionFromEnv(env) {
  return {
    prediction: env.DRACO_UV_PRED ?? 'auto',
    seams: env.DRACO_UV_SEAMS ?? 'context',
    anchors: env.DRACO_UV_ANCHORS || undefined,
  };
}

function tangentCompressionFromEnv(env) {
  return {prediction: env.DRACO_TANGENT_PRED ?? 'auto'};
}

export default {
  onProgramReady: async ({io}) => {
    await registerDracoUv(io, {
      texCoordCompression: texCoordCompressionFromEnv(process.env),
      tangentCompression: tangentCompressionFromEnv(process.env),
    });
  },
};
