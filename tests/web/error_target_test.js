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
 * @fileoverview Error targets in the web package's JS encoder (CTest
 * web.error_target; the web test contract, tests/web/CMakeLists.txt):
 * DracoUvOptions.SetRmse/SetTexels and createUvOptions({rmse}) /
 * ({texels, textureSize}), i.e. draco_encoder's -uv_rmse and -uv_texels.
 *
 * On a sheared grid mesh built here (integer positions and texture
 * coordinates, which JS and Draco's OBJ reader hold as the same floats):
 *   - with a named lossless -uv_pred the JS encoder writes the same bytes
 *     as native draco_encoder with the same flags (both search -qt only);
 *   - with the target alone (the encoder picks the scheme; lossless only in
 *     WebAssembly, which has no decoder to measure the Laplacian with) the
 *     decoded texture coordinates meet the target, measured per UV vertex
 *     (eq. 9) against the mesh's own;
 *   - values that are not finite and positive are refused with a message.
 *
 *   node tests/web/error_target_test.js
 *
 * Environment: DRACO_UV_WEB_PACKAGE (the package folder), DRACO_UV_BUILD_DIR
 * (draco/draco_encoder). Exit 0 pass, 1 fail, 77 skip.
 */
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');
const {execFileSync} = require('child_process');

const kQp = 11;
const kQt = 12;
const kCl = 10;
const kGrid = 24;  // Vertices per side.

let failures = 0;
function check(condition, message) {
  if (!condition) {
    ++failures;
    console.log(`FAIL: ${message}`);
  }
}

// A kGrid x kGrid grid, two triangles per cell: positions (i, j, (i*j)%5),
// texture coordinates (3i + j%2, 3j), all integers. Returns per-corner
// arrays for MeshBuilder, the OBJ text (values in order of first use, as
// the JS encoder's deduplication keeps them) and the UV of each (i, j).
function gridMesh() {
  const corners = [];
  for (let j = 0; j + 1 < kGrid; ++j) {
    for (let i = 0; i + 1 < kGrid; ++i) {
      corners.push([i, j], [i + 1, j], [i + 1, j + 1]);
      corners.push([i, j], [i + 1, j + 1], [i, j + 1]);
    }
  }
  const position = ([i, j]) => [i, j, (i * j) % 5];
  const uv = ([i, j]) => [3 * i + (j % 2), 3 * j];
  const ids = new Map();
  const lines = {v: [], vt: []};
  const refs = corners.map((corner) => {
    const key = corner.join();
    if (!ids.has(key)) {
      ids.set(key, ids.size + 1);
      lines.v.push(`v ${position(corner).join(' ')}`);
      lines.vt.push(`vt ${uv(corner).join(' ')}`);
    }
    return ids.get(key);
  });
  const faces = [];
  for (let c = 0; c < refs.length; c += 3) {
    faces.push('f ' + [0, 1, 2].map((k) => `${refs[c + k]}/${refs[c + k]}`)
        .join(' '));
  }
  return {
    numCorners: corners.length,
    positions: Float32Array.from(corners.flatMap(position)),
    uvs: Float32Array.from(corners.flatMap(uv)),
    objText: lines.v.concat(lines.vt, faces).join('\n') + '\n',
    uvAt: (i, j) => uv([i, j]),
  };
}

// Encodes |grid| with a JS Encoder whose TEX_COORD coding is |options|.
function encode(encoderModule, grid, options) {
  const mesh = new encoderModule.Mesh();
  const builder = new encoderModule.MeshBuilder();
  const faces = Int32Array.from({length: grid.numCorners}, (_, i) => i);
  builder.AddFacesToMesh(mesh, grid.numCorners / 3, faces);
  builder.AddFloatAttribute(mesh, encoderModule.POSITION, grid.numCorners, 3,
                            grid.positions);
  builder.AddFloatAttribute(mesh, encoderModule.TEX_COORD, grid.numCorners, 2,
                            grid.uvs);
  const encoder = new encoderModule.Encoder();
  const array = new encoderModule.DracoInt8Array();
  try {
    encoder.SetAttributeQuantization(encoderModule.POSITION, kQp);
    encoder.SetAttributeQuantization(encoderModule.TEX_COORD, kQt);
    encoder.SetSpeedOptions(10 - kCl, 10 - kCl);
    check(encoder.SetAttributeUvCompression(encoderModule.TEX_COORD, options),
          `SetAttributeUvCompression: ${encoder.GetUvCompressionMessage()}`);
    const size = encoder.EncodeMeshToDracoBuffer(mesh, array);
    const bytes = new Uint8Array(size);
    for (let i = 0; i < size; ++i) bytes[i] = array.GetValue(i);
    return {bytes: Buffer.from(bytes.buffer),
            message: encoder.GetUvCompressionMessage()};
  } finally {
    for (const object of [array, encoder, builder, mesh]) {
      encoderModule.destroy(object);
    }
  }
}

// Eq. (9) of the decoded texture coordinates against |grid|'s: the decoded
// positions round to the grid's integers, which name each UV vertex.
function decodedRmse(decoderModule, grid, bytes) {
  const decoder = new decoderModule.Decoder();
  const mesh = new decoderModule.Mesh();
  const values = {};
  try {
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    if (!status.ok()) throw new Error(status.error_msg());
    for (const [name, type] of [['pos', decoderModule.POSITION],
                                ['uv', decoderModule.TEX_COORD]]) {
      const att =
          decoder.GetAttribute(mesh, decoder.GetAttributeId(mesh, type));
      const array = new decoderModule.DracoFloat32Array();
      decoder.GetAttributeFloatForAllPoints(mesh, att, array);
      values[name] = Float32Array.from({length: array.size()},
                                       (_, i) => array.GetValue(i));
      decoderModule.destroy(array);
    }
  } finally {
    decoderModule.destroy(mesh);
    decoderModule.destroy(decoder);
  }
  let sum2 = 0;
  const points = values.uv.length / 2;
  for (let p = 0; p < points; ++p) {
    const expected = grid.uvAt(Math.round(values.pos[3 * p]),
                               Math.round(values.pos[3 * p + 1]));
    sum2 += (values.uv[2 * p] - expected[0]) ** 2 +
        (values.uv[2 * p + 1] - expected[1]) ** 2;
  }
  return Math.sqrt(sum2 / points);
}

function checkRefusals(draco, encoderModule) {
  const options = new encoderModule.DracoUvOptions();
  for (const bad of [0, -1, NaN, Infinity]) {
    check(!options.SetRmse(bad), `SetRmse(${bad}) accepted`);
    check(!options.SetTexels(bad, 4096), `SetTexels(${bad}) accepted`);
  }
  check(/positive/.test(options.GetErrorMessage()),
        `no reason given: '${options.GetErrorMessage()}'`);
  check(!options.SetTexels(0.5, 0), 'SetTexels with texture size 0 accepted');
  encoderModule.destroy(options);
  for (const settings of [{rmse: 0}, {rmse: 'abc'}, {texels: -1}]) {
    let threw = false;
    try {
      encoderModule.destroy(draco.createUvOptions(encoderModule, settings));
    } catch (error) {
      threw = /texCoordCompression\.(rmse|texels)/.test(error.message);
    }
    check(threw, `createUvOptions(${JSON.stringify(settings)}) did not throw`);
  }
}

async function main() {
  const packageDir = process.env.DRACO_UV_WEB_PACKAGE;
  const buildDir = process.env.DRACO_UV_BUILD_DIR;
  if (!packageDir || !fs.existsSync(path.join(packageDir, 'draco3d.js'))) {
    console.log('SKIP: DRACO_UV_WEB_PACKAGE is not a built web package');
    process.exit(77);
  }
  const encoderPath = buildDir && path.join(buildDir, 'draco', 'draco_encoder');
  if (!encoderPath || !fs.existsSync(encoderPath)) {
    console.log('SKIP: no native draco_encoder in DRACO_UV_BUILD_DIR');
    process.exit(77);
  }
  const draco = require(path.resolve(packageDir, 'draco3d.js'));
  const encoderModule = await draco.createEncoderModule({});
  const decoderModule = await draco.createDecoderModule({});
  checkRefusals(draco, encoderModule);
  const grid = gridMesh();
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'draco-uv-target-'));
  const objFile = path.join(dir, 'grid.obj');
  fs.writeFileSync(objFile, grid.objText);
  const range = 3 * (kGrid - 1) + 1;  // Of the texture coordinates.
  const cases = [
    {settings: {prediction: 'weighted', rmse: 1.5e-3 * range},
     flags: ['-uv_pred', 'weighted', '-uv_rmse', `${1.5e-3 * range}`]},
    {settings: {prediction: 'weighted', texels: 0.5, textureSize: 64},
     flags: ['-uv_pred', 'weighted', '-uv_texels', '0.5',
             '-uv_texture_size', '64']},
    {settings: {rmse: 1e-4 * range}},
    {settings: {texels: 2, textureSize: 1024}},
  ];
  for (const {settings, flags} of cases) {
    const name = JSON.stringify(settings);
    const options = draco.createUvOptions(encoderModule, settings);
    const result = encode(encoderModule, grid, options);
    encoderModule.destroy(options);
    check(/UV error target/.test(result.message), `${name}: ${result.message}`);
    const target = settings.rmse || settings.texels / settings.textureSize;
    const rmse = decodedRmse(decoderModule, grid, result.bytes);
    check(rmse <= target, `${name}: decoded RMSE ${rmse} above ${target}`);
    if (flags) {
      const outFile = path.join(dir, 'grid.drc');
      execFileSync(encoderPath, ['-i', objFile, '-o', outFile, '-qp',
                                 `${kQp}`, '-qt', `${kQt}`, '-cl', `${kCl}`]
                       .concat(flags), {stdio: 'pipe'});
      check(result.bytes.equals(fs.readFileSync(outFile)),
            `${name}: bytes differ from draco_encoder ${flags.join(' ')}`);
    }
  }
  fs.rmSync(dir, {recursive: true, force: true});
  console.log(failures === 0 ? 'PASS' : `${failures} failure(s)`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.log(`FAIL: ${error.stack || error}`);
  process.exit(1);
});
