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

// Decodes every KHR_draco_mesh_compression primitive of a glTF or GLB file
// with a stock Draco decoder from npm (draco3d), the way three.js's
// DRACOLoader does: DecodeArrayToMesh, then each attribute of the
// extension's map by unique id.
//
//   node decode_gltf_draco.js <draco3d module folder> <file.gltf|file.glb>
//
// Prints the decoder's version once, then one line per primitive, with the
// attributes of the primitive's KHR_draco_mesh_compression map:
//   "primitive <mesh>.<primitive> ok <names> points=<n>"
//   "primitive <mesh>.<primitive> error <names> <decoder message>"
// Exits 0 when every primitive was attempted (decoding errors are output,
// not failures of this script), 1 when the file cannot be read.
'use strict';

const fs = require('fs');
const path = require('path');

const kGlbMagic = 0x46546c67;  // "glTF"
const kJsonChunk = 0x4e4f534a;  // "JSON"
const kBinChunk = 0x004e4942;  // "BIN\0"

// Returns {json, bin} of a .glb, or of a .gltf and its first buffer.
function readGltf(file) {
  const data = fs.readFileSync(file);
  if (data.length >= 12 && data.readUInt32LE(0) === kGlbMagic) {
    let json = null;
    let bin = null;
    for (let offset = 12; offset + 8 <= data.length;) {
      const length = data.readUInt32LE(offset);
      const type = data.readUInt32LE(offset + 4);
      const chunk = data.subarray(offset + 8, offset + 8 + length);
      if (type === kJsonChunk) json = JSON.parse(chunk.toString('utf8'));
      if (type === kBinChunk) bin = chunk;
      offset += 8 + length;
    }
    return {json, bin};
  }
  const json = JSON.parse(data.toString('utf8'));
  const uri = json.buffers && json.buffers.length ? json.buffers[0].uri : null;
  const bin = uri ? fs.readFileSync(path.join(path.dirname(file), uri)) : null;
  return {json, bin};
}

function bufferViewBytes(gltf, index) {
  const view = gltf.json.bufferViews[index];
  const start = view.byteOffset || 0;
  return new Int8Array(gltf.bin.buffer, gltf.bin.byteOffset + start,
                       view.byteLength);
}

// Decodes one Draco buffer and reads every attribute of |attributeIds| the
// way DRACOLoader does; returns "" or the error.
function decodePrimitive(draco, bytes, attributeIds, result) {
  const decoder = new draco.Decoder();
  const mesh = new draco.Mesh();
  try {
    const status = decoder.DecodeArrayToMesh(bytes, bytes.byteLength, mesh);
    if (!status.ok()) return status.error_msg();
    for (const name of Object.keys(attributeIds)) {
      const attribute = decoder.GetAttributeByUniqueId(mesh, attributeIds[name]);
      const values = new draco.DracoFloat32Array();
      const read = decoder.GetAttributeFloatForAllPoints(mesh, attribute, values);
      draco.destroy(values);
      if (!read) return 'cannot read ' + name;
    }
    result.points = mesh.num_points();
    return '';
  } finally {
    draco.destroy(mesh);
    draco.destroy(decoder);
  }
}

async function main() {
  if (process.argv.length !== 4) {
    console.error('usage: node decode_gltf_draco.js <draco3d folder> <file>');
    process.exit(2);
  }
  const moduleDir = path.resolve(process.argv[2]);
  const draco3d = require(moduleDir);
  const version = require(path.join(moduleDir, 'package.json')).version;
  let gltf;
  try {
    gltf = readGltf(process.argv[3]);
  } catch (error) {
    console.error('cannot read ' + process.argv[3] + ': ' + error.message);
    process.exit(1);
  }
  const draco = await draco3d.createDecoderModule({});
  console.log('draco3d ' + version);
  (gltf.json.meshes || []).forEach((mesh, m) => {
    mesh.primitives.forEach((primitive, p) => {
      const extension = (primitive.extensions || {}).KHR_draco_mesh_compression;
      if (!extension) return;
      const bytes = bufferViewBytes(gltf, extension.bufferView);
      const names = Object.keys(extension.attributes).sort().join(',');
      const result = {};
      const error = decodePrimitive(draco, bytes, extension.attributes, result);
      console.log('primitive ' + m + '.' + p + ' ' +
                  (error ? 'error ' + names + ' ' + error
                         : 'ok ' + names + ' points=' + result.points));
    });
  });
}

main();
