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

/**
 * What the Node pipeline tests (gltf_transform_test.mjs,
 * gltf_pipeline_test.js) share: their environment and skip rules, the test
 * assets, reading GLBs' JSON and Draco buffers, decoding Draco buffers with a
 * given decoder module, and a canonical digest of a glTF-Transform
 * Document's triangles that does not depend on vertex or corner order.
 */
'use strict';

import crypto from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';

export const MARKER = 'DRACOUV_attribute_compression';
// What the marker adds to a GLB's JSON chunk at most: its name in two lists,
// quoted with a comma, plus the chunk's padding to 4 bytes.
export const MARKER_JSON_BYTES = 2 * (MARKER.length + 3) + 3;

// Textured assets of Draco's testdata (TEXCOORD_0, MultiUVTest also
// TEXCOORD_1; Fox is skinned) and Box, which has no texture coordinates.
export const ASSETS = [
  {name: 'Lantern', file: 'Lantern/glTF/Lantern.gltf', uv: true},
  {name: 'CesiumMilkTruck', file: 'CesiumMilkTruck/glTF/CesiumMilkTruck.gltf',
   uv: true},
  {name: 'Fox', file: 'Fox/glTF/Fox.gltf', uv: true},
  {name: 'MultiUVTest', file: 'MultiUVTest/glTF/MultiUVTest.gltf', uv: true},
  {name: 'Box', file: 'Box/glTF_Binary/Box.glb', uv: false},
];

// The texture coordinate codings the tests write (all lossless). auto may
// keep ids stock decoders know (Draco's own prediction, or its portable or
// parallelogram prediction when smaller); the others write draco-uv's ids on
// every mesh with texture seams. auto with stock seams pays for the marker
// (neverLarger): its files are never larger than stock coding's.
export const UV_SETTINGS = [
  {name: 'auto', texCoordCompression: {prediction: 'auto'}, forcesIds: false,
   neverLarger: true},
  {name: 'auto+context',
   texCoordCompression: {prediction: 'auto', seams: 'context'},
   forcesIds: true, neverLarger: false},
  {name: 'weighted_multi', texCoordCompression: {prediction: 'weighted_multi'},
   forcesIds: true, neverLarger: false},
];

// Assets with large enough textured meshes that every draco-uv coding that
// writes draco-uv ids makes their Draco buffers smaller (MultiUVTest's 96
// vertices may grow with weighted_multi); auto may keep stock coding.
export const LARGE_ASSETS = ['Lantern', 'CesiumMilkTruck', 'Fox'];

export function skip(why) {
  console.log(`SKIP: ${why}`);
  process.exit(77);
}

/**
 * The web test contract's environment; skips (exit 77) when the package,
 * the testdata or tests/web/node_modules is missing.
 */
export function environment(here) {
  const env = {
    packageDir: process.env.DRACO_UV_WEB_PACKAGE,
    testdata: process.env.DRACO_TESTDATA,
    buildDir: process.env.DRACO_UV_BUILD_DIR,
  };
  if (!env.packageDir || !fs.existsSync(path.join(env.packageDir,
                                                  'package.json'))) {
    skip('DRACO_UV_WEB_PACKAGE is not a package folder');
  }
  if (!env.testdata || !fs.existsSync(env.testdata)) {
    skip('DRACO_TESTDATA is not set or missing');
  }
  const modules = path.join(here, 'node_modules');
  for (const name of ['draco3d-uv', 'draco3d', '@gltf-transform/core',
                      '@gltf-transform/cli', 'gltf-pipeline']) {
    if (!fs.existsSync(path.join(modules, name, 'package.json'))) {
      skip(`tests/web/node_modules/${name} is missing ` +
           '(tests/web/install-packages.sh installs it)');
    }
  }
  return env;
}

/** Fails the test with |message| unless |condition|. */
export function check(condition, message) {
  if (!condition) {
    throw new Error(message);
  }
}

/** The JSON and BIN chunks of a GLB. */
export function parseGlb(bytes) {
  const view = Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  check(view.readUInt32LE(0) === 0x46546c67, 'not a GLB');
  let offset = 12;
  let json = null;
  let bin = null;
  while (offset < view.length) {
    const length = view.readUInt32LE(offset);
    const type = view.readUInt32LE(offset + 4);
    const chunk = view.subarray(offset + 8, offset + 8 + length);
    if (type === 0x4e4f534a) {
      json = JSON.parse(chunk.toString('utf8'));
    } else if (type === 0x004e4942) {
      bin = chunk;
    }
    offset += 8 + length;
  }
  return {json, bin};
}

/** True when the glTF JSON lists the marker in both lists. */
export function hasMarker(json) {
  const used = (json.extensionsUsed || []).includes(MARKER);
  const required = (json.extensionsRequired || []).includes(MARKER);
  check(used === required,
        `${MARKER} in extensionsUsed (${used}) but not in ` +
        `extensionsRequired (${required}) or the reverse`);
  return used;
}

/** The Draco buffers of a GLB's primitives (each bufferView once). */
export function dracoBuffers(glb) {
  const {json, bin} = parseGlb(glb);
  const views = new Set();
  for (const mesh of json.meshes || []) {
    for (const primitive of mesh.primitives) {
      const draco = (primitive.extensions || {}).KHR_draco_mesh_compression;
      if (draco) {
        views.add(draco.bufferView);
      }
    }
  }
  return [...views].map((index) => {
    const view = json.bufferViews[index];
    return bin.subarray(view.byteOffset || 0,
                        (view.byteOffset || 0) + view.byteLength);
  });
}

/** Decodes a Draco mesh buffer: '' when it decodes, else the error. */
export function decodeError(decoderModule, bytes) {
  const decoder = new decoderModule.Decoder();
  const mesh = new decoderModule.Mesh();
  try {
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    return status.ok() ? '' : (status.error_msg() || 'failed');
  } finally {
    decoderModule.destroy(mesh);
    decoderModule.destroy(decoder);
  }
}

/** The bytes of a GLB's Draco buffers. */
export function dracoBytes(glb) {
  return dracoBuffers(glb).reduce((total, b) => total + b.length, 0);
}

/**
 * Checks the sizes of a file with draco-uv's coding against |reference|
 * (the same asset with stock coding): its Draco buffers are smaller, and the
 * file is, but for the marker's JSON when |marked|.
 */
export function checkSmaller(glb, reference, marked) {
  const [bytes, referenceBytes] = [dracoBytes(glb), dracoBytes(reference)];
  const allowed = reference.length + (marked ? MARKER_JSON_BYTES : 0) - 1;
  check(bytes < referenceBytes && glb.length <= allowed,
        `${glb.length} bytes (Draco ${bytes}), stock coding's ` +
        `${reference.length} (Draco ${referenceBytes})`);
}

/**
 * Checks that a file (bytes or a size) written with prediction 'auto' and
 * stock seams is not larger than |reference| (the same asset with stock
 * coding), and smaller when |marked|: auto keeps the marker only where
 * draco-uv saves more than the marker costs.
 */
export function checkNotLarger(file, reference, marked) {
  const [size, referenceSize] = [file, reference].map(
      (f) => typeof f === 'number' ? f : f.length);
  check(marked ? size < referenceSize : size <= referenceSize,
        `auto: ${size} bytes${marked ? ', marked' : ''}, stock coding's ` +
        `${referenceSize}`);
}

/**
 * How many of the GLB's Draco buffers |decoderModule| fails on, and the
 * number of buffers.
 */
export function countUndecodable(decoderModule, glb) {
  const buffers = dracoBuffers(glb);
  const failures = buffers.filter((b) => decodeError(decoderModule, b) !== '');
  return {failed: failures.length, total: buffers.length};
}

/**
 * A digest per primitive of a Document: the multiset of its triangles, each
 * triangle the set of its corners' attribute values (all semantics), so two
 * encodings of the same geometry give the same digests whatever vertex and
 * corner order the decoder returns.
 */
export function geometryDigests(document) {
  const digests = [];
  for (const mesh of document.getRoot().listMeshes()) {
    for (const primitive of mesh.listPrimitives()) {
      const semantics = primitive.listSemantics().slice().sort();
      const arrays = semantics.map((s) => primitive.getAttribute(s));
      const vertexKey = (i) => arrays.map((a) =>
        Array.from(a.getElement(i, [])).join(',')).join(';');
      const indices = primitive.getIndices().getArray();
      const triangles = [];
      for (let t = 0; t < indices.length; t += 3) {
        triangles.push([vertexKey(indices[t]), vertexKey(indices[t + 1]),
                        vertexKey(indices[t + 2])].sort().join('|'));
      }
      triangles.sort();
      digests.push(semantics.join(',') + ':' + crypto.createHash('sha256')
          .update(triangles.join('\n')).digest('hex').slice(0, 16));
    }
  }
  return digests;
}

/** True when some primitive of the Document has a TEXCOORD_n. */
export function hasTexCoords(document) {
  return document.getRoot().listMeshes().some((mesh) =>
    mesh.listPrimitives().some((primitive) =>
      primitive.listSemantics().some((s) => s.startsWith('TEXCOORD_'))));
}
