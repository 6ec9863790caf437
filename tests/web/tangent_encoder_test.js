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
 * @fileoverview The web package's JS encoder API for tangent prediction
 * (CTest web.tangent_encoder; the web test contract,
 * tests/web/CMakeLists.txt): DracoUvOptions.SetTangentPrediction() and
 * SetTangentQuantization(), and draco3d.js's createEncoderModule(
 * {tangentCompression}).
 *
 * Meshes: testdata/*_tangents.glb (small_torus_uv, small_cube_sphere,
 * crane_spot). The native draco_encoder first writes each losslessly
 * (Edgebreaker, no quantization: base.drc, the tangents a GENERIC
 * attribute); the package's decoder reads base.drc and the encoder module
 * builds the same mesh with MeshBuilder (the values of every point, the
 * attributes in the file's order), as glTF pipelines hand Draco glTF's
 * TANGENT. Native draco_encoder re-encodes base.drc with each row's flags
 * and the JS encoder the built mesh with the same settings. Checked, per
 * mesh and row (stock coding; -tangent_pred mikktspace, uniform, face,
 * geometric and auto with the tangents quantized by -qg, and mikktspace and
 * auto quantized by -qtg; geometric with -uv_pred auto -uv_seams context at
 * -cl 7):
 *   - the JS encoder writes the same bytes as draco_encoder, as the module
 *     default (createEncoderModule({texCoordCompression,
 *     tangentCompression})), per type (Encoder.SetAttributeUvCompression)
 *     and per attribute (ExpertEncoder.SetAttributeUvCompression on the
 *     TEX_COORD attribute);
 *   - the file decodes with the package's decoder to the stock file's
 *     tangents (quantized, at every face corner);
 *   - UsedDracoUvCoding() is true exactly when npm draco3d 1.5.9's decoder
 *     fails on the file, with an error, and always for the named schemes;
 *   - auto is never larger than stock coding; the named schemes make
 *     crane_spot smaller;
 *   - unknown names and bits out of range fail with a message listing the
 *     valid values, from the IDL and from createEncoderModule(), which
 *     rejects.
 *
 *   node tests/web/tangent_encoder_test.js
 *
 * Environment: DRACO_UV_WEB_PACKAGE (the package folder), DRACO_UV_BUILD_DIR
 * (draco/draco_encoder), DRACO_UV_SOURCE_DIR (default: two folders up).
 * Exit 0 pass, 1 fail, 77 skip.
 */
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');
const {execFileSync} = require('child_process');

const kAssets = ['small_torus_uv', 'small_cube_sphere', 'crane_spot'];
const kQp = 14;
const kQt = 12;
const kQn = 10;
// Tangent bits of the rows that quantize them as GENERIC (-qg) or with -qtg.
const kQg = 10;
const kQtg = 12;
// {name, tangent: -tangent_pred, qtg: quantize the tangents with -qtg
//  instead of -qg, uv/seams: -uv_pred/-uv_seams, cl}
const kRows = [
  {name: 'stock', tangent: '', cl: 10},
  ...['mikktspace', 'uniform', 'face', 'geometric', 'auto'].map(
      (tangent) => ({name: tangent, tangent, cl: 10})),
  {name: 'mikktspace_qtg', tangent: 'mikktspace', qtg: true, cl: 10},
  {name: 'auto_qtg', tangent: 'auto', qtg: true, cl: 10},
  {name: 'geometric+uv', tangent: 'geometric', uv: 'auto', seams: 'context',
   cl: 7},
];

function skip(why) {
  console.log(`SKIP: ${why}`);
  process.exit(77);
}

let failures = 0;
function check(condition, message) {
  if (!condition) {
    ++failures;
    console.log(`FAIL: ${message}`);
  }
  return condition;
}

/** draco_encoder's flags of |row|. */
function nativeFlags(row) {
  const flags = ['-cl', String(row.cl), '-qp', String(kQp), '-qt',
                 String(kQt), '-qn', String(kQn),
                 '-qg', String(row.qtg ? 0 : kQg)];
  if (row.qtg) flags.push('-qtg', String(kQtg));
  if (row.tangent) flags.push('-tangent_pred', row.tangent);
  if (row.uv) flags.push('-uv_pred', row.uv);
  if (row.seams) flags.push('-uv_seams', row.seams);
  return flags;
}

/** The texCoordCompression and tangentCompression settings of |row|. */
function settingsOf(row) {
  return {
    texCoordCompression: {prediction: row.uv, seams: row.seams},
    tangentCompression: {prediction: row.tangent,
                         quantizationBits: row.qtg ? kQtg : undefined},
  };
}

/** Every attribute of the mesh in |bytes|: values of every point, faces. */
function readMesh(decoderModule, bytes) {
  const decoder = new decoderModule.Decoder();
  const mesh = new decoderModule.Mesh();
  try {
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    if (!status.ok()) throw new Error(status.error_msg());
    const numPoints = mesh.num_points();
    const attributes = [];
    for (let id = 0; id < mesh.num_attributes(); ++id) {
      const att = decoder.GetAttribute(mesh, id);
      const n = att.num_components();
      const size = numPoints * n * 4;
      const ptr = decoderModule._malloc(size);
      decoder.GetAttributeDataArrayForAllPoints(mesh, att,
                                                decoderModule.DT_FLOAT32,
                                                size, ptr);
      const values = new Float32Array(decoderModule.HEAPF32.buffer, ptr,
                                      numPoints * n).slice();
      decoderModule._free(ptr);
      attributes.push({type: att.attribute_type(), components: n, values});
    }
    const indexBytes = mesh.num_faces() * 3 * 4;
    const ptr = decoderModule._malloc(indexBytes);
    decoder.GetTrianglesUInt32Array(mesh, indexBytes, ptr);
    const faces = new Uint32Array(decoderModule.HEAPU8.buffer, ptr,
                                  mesh.num_faces() * 3).slice();
    decoderModule._free(ptr);
    return {numPoints, attributes, faces};
  } finally {
    decoderModule.destroy(mesh);
    decoderModule.destroy(decoder);
  }
}

// Attribute types by the decoder's numbering (GeometryAttribute::Type).
const kTypeNames = ['POSITION', 'NORMAL', 'COLOR', 'TEX_COORD', 'GENERIC'];

function buildMesh(encoderModule, read) {
  const mesh = new encoderModule.Mesh();
  const builder = new encoderModule.MeshBuilder();
  builder.AddFacesToMesh(mesh, read.faces.length / 3,
                         Int32Array.from(read.faces));
  for (const att of read.attributes) {
    builder.AddFloatAttribute(mesh, encoderModule[kTypeNames[att.type]],
                              read.numPoints, att.components, att.values);
  }
  encoderModule.destroy(builder);
  return mesh;
}

function bytesOf(array) {
  const bytes = new Uint8Array(array.size());
  for (let i = 0; i < bytes.length; ++i) bytes[i] = array.GetValue(i);
  return Buffer.from(bytes.buffer);
}

/** Quantization of |row| on a JS Encoder (by type). */
function setUpEncoder(encoderModule, encoder, row) {
  encoder.SetAttributeQuantization(encoderModule.POSITION, kQp);
  encoder.SetAttributeQuantization(encoderModule.TEX_COORD, kQt);
  encoder.SetAttributeQuantization(encoderModule.NORMAL, kQn);
  if (!row.qtg) encoder.SetAttributeQuantization(encoderModule.GENERIC, kQg);
  encoder.SetSpeedOptions(10 - row.cl, 10 - row.cl);
}

/**
 * Encodes |read| with a JS Encoder of |encoderModule| (|options|: a
 * DracoUvOptions set per type, else the module default applies).
 */
function encodeWithEncoder(encoderModule, read, row, options) {
  const mesh = buildMesh(encoderModule, read);
  const encoder = new encoderModule.Encoder();
  const array = new encoderModule.DracoInt8Array();
  try {
    setUpEncoder(encoderModule, encoder, row);
    if (options) {
      check(encoder.SetAttributeUvCompression(encoderModule.TEX_COORD,
                                              options),
            `SetAttributeUvCompression: ${encoder.GetUvCompressionMessage()}`);
    }
    const size = encoder.EncodeMeshToDracoBuffer(mesh, array);
    return {bytes: size > 0 ? bytesOf(array) : null,
            used: encoder.UsedDracoUvCoding(),
            message: encoder.GetUvCompressionMessage()};
  } finally {
    encoderModule.destroy(array);
    encoderModule.destroy(encoder);
    encoderModule.destroy(mesh);
  }
}

/** The same through an ExpertEncoder, |options| on the TEX_COORD id. */
function encodeWithExpert(encoderModule, read, row, options) {
  const mesh = buildMesh(encoderModule, read);
  const encoder = new encoderModule.ExpertEncoder(mesh);
  const array = new encoderModule.DracoInt8Array();
  try {
    const bits = {POSITION: kQp, TEX_COORD: kQt, NORMAL: kQn,
                  GENERIC: row.qtg ? 0 : kQg};
    read.attributes.forEach((att, id) => {
      const b = bits[kTypeNames[att.type]];
      if (b) encoder.SetAttributeQuantization(id, b);
    });
    encoder.SetSpeedOptions(10 - row.cl, 10 - row.cl);
    const uv = read.attributes.findIndex(
        (att) => kTypeNames[att.type] === 'TEX_COORD');
    check(encoder.SetAttributeUvCompression(uv, options),
          `ExpertEncoder.SetAttributeUvCompression: ` +
          encoder.GetUvCompressionMessage());
    const size = encoder.EncodeToDracoBuffer(true, array);
    return {bytes: size > 0 ? bytesOf(array) : null,
            used: encoder.UsedDracoUvCoding(),
            message: encoder.GetUvCompressionMessage()};
  } finally {
    encoderModule.destroy(array);
    encoderModule.destroy(encoder);
    encoderModule.destroy(mesh);
  }
}

/** The quantized tangents (GENERIC) at every face corner, as a string. */
function quantizedTangents(decoderModule, bytes) {
  const decoder = new decoderModule.Decoder();
  const mesh = new decoderModule.Mesh();
  try {
    decoder.SkipAttributeTransform(decoderModule.GENERIC);
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    if (!status.ok()) return `error: ${status.error_msg()}`;
    const att = decoder.GetAttribute(
        mesh, decoder.GetAttributeId(mesh, decoderModule.GENERIC));
    const values = new decoderModule.DracoInt32Array();
    decoder.GetAttributeInt32ForAllPoints(mesh, att, values);
    const face = new decoderModule.DracoInt32Array();
    const corners = [];
    for (let f = 0; f < mesh.num_faces(); ++f) {
      decoder.GetFaceFromMesh(mesh, f, face);
      for (let k = 0; k < 3; ++k) {
        const p = face.GetValue(k);
        for (let i = 0; i < 4; ++i) corners.push(values.GetValue(p * 4 + i));
      }
    }
    decoderModule.destroy(face);
    decoderModule.destroy(values);
    return corners.join(',');
  } finally {
    decoderModule.destroy(mesh);
    decoderModule.destroy(decoder);
  }
}

/** The error of npm draco3d's decoder on |bytes|, or null if it decodes. */
function stockDecodeError(stockModule, bytes) {
  const decoder = new stockModule.Decoder();
  const mesh = new stockModule.Mesh();
  try {
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    return status.ok() ? null : (status.error_msg() || '(no message)');
  } finally {
    stockModule.destroy(mesh);
    stockModule.destroy(decoder);
  }
}

async function checkNames(draco3d, encoderModule) {
  const options = new encoderModule.DracoUvOptions();
  check(!options.SetTangentPrediction('mikkt') &&
        /mikktspace.*geometric.*auto/.test(options.GetErrorMessage()),
        `SetTangentPrediction('mikkt'): "${options.GetErrorMessage()}"`);
  for (const bits of [-1, 22]) {
    check(!options.SetTangentQuantization(bits) &&
          /-qtg needs 1 to 21/.test(options.GetErrorMessage()),
          `SetTangentQuantization(${bits}): "${options.GetErrorMessage()}"`);
  }
  check(options.SetTangentPrediction('') && options.SetTangentQuantization(0),
        'SetTangentPrediction(\'\') or SetTangentQuantization(0) fails');
  encoderModule.destroy(options);
  for (const [tangentCompression, pattern] of [
    [{prediction: 'mikkt'}, /tangentCompression\.prediction: .*mikktspace/],
    [{quantizationBits: 30}, /tangentCompression\.quantizationBits: .*1 to 21/],
    [{quantizationBits: 8.5}, /tangentCompression\.quantizationBits: .*whole/],
  ]) {
    let message = 'resolved';
    try {
      await draco3d.createEncoderModule({tangentCompression});
    } catch (error) {
      message = error.message;
    }
    check(pattern.test(message),
          `createEncoderModule(${JSON.stringify(tangentCompression)}): ` +
          `"${message}"`);
  }
}

async function main() {
  const packageDir = process.env.DRACO_UV_WEB_PACKAGE;
  const buildDir = process.env.DRACO_UV_BUILD_DIR;
  const source = process.env.DRACO_UV_SOURCE_DIR ||
      path.resolve(__dirname, '..', '..');
  if (!packageDir || !fs.existsSync(path.join(packageDir, 'package.json'))) {
    skip('DRACO_UV_WEB_PACKAGE is not a package folder');
  }
  const nativeEncoder = path.join(buildDir || '', 'draco', 'draco_encoder');
  if (!buildDir || !fs.existsSync(nativeEncoder)) {
    skip(`no native draco_encoder in DRACO_UV_BUILD_DIR (${buildDir})`);
  }
  for (const name of ['draco3d-uv', 'draco3d']) {
    if (!fs.existsSync(path.join(__dirname, 'node_modules', name))) {
      skip(`tests/web/node_modules/${name} is missing ` +
           '(tests/web/install-packages.sh installs it)');
    }
  }
  const draco3d = require('draco3d-uv');
  const decoderModule = await draco3d.createDecoderModule({});
  const stockModule = await require('draco3d').createDecoderModule({});
  const plainModule = await draco3d.createEncoderModule({});
  await checkNames(draco3d, plainModule);
  // The module whose default each row sets (as glTF pipelines do), made
  // with a tangent default as createEncoderModule's option sets it.
  const defaultModule = await draco3d.createEncoderModule(
      {tangentCompression: {prediction: 'auto'}});

  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'tangent-encoder-'));
  try {
    for (const asset of kAssets) {
      const base = path.join(work, `${asset}.base.drc`);
      execFileSync(nativeEncoder, [
        '-i', path.join(source, 'testdata', `${asset}_tangents.glb`),
        '-o', base, '-cl', '10', '-qp', '0', '-qt', '0', '-qn', '0',
        '-qg', '0'], {stdio: 'ignore'});
      const read = readMesh(decoderModule, fs.readFileSync(base));
      const sizes = {};
      let stock;
      for (const row of kRows) {
        const out = path.join(work, `${asset}.${row.name}.drc`);
        execFileSync(nativeEncoder,
                     ['-i', base, '-o', out, ...nativeFlags(row)],
                     {stdio: 'ignore'});
        const native = fs.readFileSync(out);
        const what = `${asset} ${row.name}`;
        // The module default, as glTF pipelines set it.
        draco3d.setUvDefault(defaultModule, settingsOf(row).texCoordCompression,
                             settingsOf(row).tangentCompression);
        const byDefault = encodeWithEncoder(defaultModule, read, row, null);
        const options = draco3d.createUvOptions(
            plainModule, settingsOf(row).texCoordCompression,
            settingsOf(row).tangentCompression);
        const byType = encodeWithEncoder(plainModule, read, row, options);
        const byId = encodeWithExpert(plainModule, read, row, options);
        plainModule.destroy(options);
        for (const [how, result] of [['default', byDefault],
                                     ['per type', byType],
                                     ['per attribute', byId]]) {
          check(result.bytes && result.bytes.equals(native),
                `${what} (${how}): ${result.bytes ? result.bytes.length :
                                                    result.message} bytes, ` +
                `draco_encoder ${native.length}`);
        }
        sizes[row.name] = native.length;
        const tangents = quantizedTangents(decoderModule, native);
        if (row.name === 'stock') {
          // Stock coding with the tangents quantized by -qtg, the reference
          // of the -qtg rows.
          const stockQtg = path.join(work, `${asset}.stock_qtg.drc`);
          execFileSync(nativeEncoder,
                       ['-i', base, '-o', stockQtg,
                        ...nativeFlags({cl: 10, qtg: true})],
                       {stdio: 'ignore'});
          const qtgBytes = fs.readFileSync(stockQtg);
          stock = {
            qg: {tangents, size: native.length},
            qtg: {tangents: quantizedTangents(decoderModule, qtgBytes),
                  size: qtgBytes.length},
          };
          continue;
        }
        const reference = stock[row.qtg ? 'qtg' : 'qg'];
        check(tangents === reference.tangents,
              `${what}: decodes to other tangents than stock coding's`);
        const stockError = stockDecodeError(stockModule, native);
        check(byDefault.used === (stockError !== null),
              `${what}: UsedDracoUvCoding ${byDefault.used}, npm draco3d ` +
              `${stockError ? `fails: ${stockError}` : 'decodes it'}`);
        if (row.tangent !== 'auto') {
          check(byDefault.used, `${what}: no draco-uv ids written`);
          check(/Tangent prediction/.test(byDefault.message),
                `${what}: message "${byDefault.message}"`);
        }
        if (row.tangent === 'auto') {
          check(native.length <= reference.size,
                `${what}: ${native.length} bytes, stock ${reference.size}`);
        } else if (asset === 'crane_spot' && !row.uv) {
          check(native.length < reference.size,
                `${what}: ${native.length} bytes, stock ${reference.size}`);
        }
      }
      console.log(`${asset}: ` + Object.entries(sizes)
          .map(([name, size]) => `${name} ${size}`).join(', '));
    }
  } finally {
    fs.rmSync(work, {recursive: true, force: true});
  }
  console.log(`tangent_encoder_test: ${failures} failures`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
