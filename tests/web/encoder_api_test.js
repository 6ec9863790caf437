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
 * @fileoverview The web package's JS encoder API for draco-uv's coders
 * (CTest web.encoder_api; the web test contract, tests/web/CMakeLists.txt):
 * DracoUvOptions, DracoUvModule, Encoder/ExpertEncoder
 * SetAttributeUvCompression, UsedDracoUvCoding, and draco3d.js's
 * createEncoderModule({texCoordCompression}) and createUvOptions.
 *
 * Meshes: draco-uv's textured test meshes (crane_spot, torus_uv,
 * bumpy_cube_sphere) and Draco's cube_att.obj, read by an OBJ reader that
 * parses numbers as Draco's does, built in the encoder module with
 * MeshBuilder (one point per face corner; the encoder deduplicates). For
 * each mesh and setting (auto, weighted_multi, auto + context seams,
 * laplacian_mv; per type, per attribute and as the module default):
 *   - the JS encoder writes the same bytes as the native draco_encoder with
 *     the same flags, given the same mesh (an OBJ written in the order the
 *     encoder module sees the values): one configuration path;
 *   - with no setting, the same bytes as native stock coding;
 *   - the lossless settings decode with the package's decoder to the stock
 *     encode's quantized positions and texture coordinates, corner by
 *     corner; laplacian_mv decodes to the same faces;
 *   - UsedDracoUvCoding() is true exactly when npm draco3d 1.5.9's decoder
 *     fails on the file (with an error), and GetNumEncodesWithDracoUvIds()
 *     counts those encodes; stock encodes decode with draco3d;
 *   - auto is never larger than stock and smaller whenever it wrote draco-uv
 *     ids; every draco-uv setting is smaller than stock over all meshes;
 *   - unknown names and inconsistent options fail with a message listing
 *     the valid values, from the IDL, createUvOptions() and
 *     createEncoderModule(), which rejects;
 *   - in a glTF write (DracoUvModule.BeginGltfWrite/EndGltfWrite), auto's
 *     first encode keeps draco-uv ids only if they save more than the
 *     marker's 76 bytes, else writes the stock bytes (both happen over the
 *     meshes); after an encode that kept them, later ones keep auto's
 *     choice; after EndGltfWrite auto weighs Draco bytes only again.
 *
 *   node tests/web/encoder_api_test.js
 *
 * Environment: DRACO_UV_WEB_PACKAGE (the package folder), DRACO_UV_BUILD_DIR
 * (draco/draco_encoder), DRACO_UV_SOURCE_DIR (default: two folders up),
 * DRACO_TESTDATA (Draco's testdata). Exit 0 pass, 1 fail, 77 skip.
 */
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');
const {execFileSync} = require('child_process');

// draco_encoder's flags of every encode here, and the same on the JS side.
const kQp = 11;
const kQt = 12;
const kQn = 8;
const kCl = 10;
const kSettings = [
  {name: 'auto', prediction: 'auto', lossless: true},
  {name: 'weighted_multi', prediction: 'weighted_multi', lossless: true},
  {name: 'auto+context', prediction: 'auto', seams: 'context',
   lossless: true},
  {name: 'laplacian_mv', prediction: 'laplacian_mv', lossless: false},
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
}

// Draco's ParseFloat (src/draco/io/parser_utils.cc), operation by operation
// in double precision, then rounded to float32 as Draco stores it: the JS
// mesh gets the exact floats the native OBJ reader gets.
function dracoParseFloat(text) {
  let i = 0;
  let sign = 1;
  if (text[i] === '-' || text[i] === '+') {
    sign = text[i] === '-' ? -1 : 1;
    ++i;
  }
  let v = 0.0;
  while (i < text.length && text[i] >= '0' && text[i] <= '9') {
    v *= 10.0;
    v += text.charCodeAt(i++) - 48;
  }
  if (text[i] === '.') {
    ++i;
    let fraction = 1.0;
    while (i < text.length && text[i] >= '0' && text[i] <= '9') {
      fraction *= 0.1;
      v += (text.charCodeAt(i++) - 48) * fraction;
    }
  }
  if (text[i] === 'e' || text[i] === 'E') {
    v *= Math.pow(10.0, parseInt(text.slice(i + 1), 10));
  }
  return Math.fround(sign * v);
}

// A triangle OBJ with texture coordinates (and optionally normals): the
// corners' values as Draco's reader stores them (float32), and the text of
// each value for writing it again.
function readObj(file) {
  const lists = {v: [], vt: [], vn: []};
  const corners = [];
  for (const line of fs.readFileSync(file, 'utf8').split('\n')) {
    const words = line.trim().split(/\s+/);
    if (words[0] in lists) {
      const size = words[0] === 'vt' ? 2 : 3;
      const text = words.slice(1, 1 + size);
      lists[words[0]].push({text, value: text.map(dracoParseFloat)});
    } else if (words[0] === 'f') {
      if (words.length !== 4) throw new Error(`${file}: not a triangle`);
      for (const corner of words.slice(1)) {
        const [v, vt, vn] = corner.split('/').map((x) => parseInt(x, 10) - 1);
        corners.push({v, vt, vn});
      }
    }
  }
  const withNormals = lists.vn.length > 0;
  const channels = [['v', 3], ['vt', 2]].concat(withNormals ? [['vn', 3]] :
                                                              []);
  return {lists, corners, channels};
}

// The corner arrays for MeshBuilder, and an OBJ of the same mesh whose value
// lists hold each distinct value once, in order of first use: the order in
// which the encoder module's deduplication keeps the per-corner values, so
// that native draco_encoder sees exactly the mesh the JS encoder sees.
function prepareMesh(obj) {
  const numCorners = obj.corners.length;
  const arrays = {};
  const objLines = [];
  const faceRefs = obj.corners.map(() => []);
  for (const [key, size] of obj.channels) {
    const values = new Float32Array(numCorners * size);
    const bits = new Uint32Array(values.buffer);
    const firstUse = new Map();
    obj.corners.forEach((corner, c) => {
      const entry = obj.lists[key][corner[key]];
      values.set(entry.value, c * size);
      const id = Array.from(bits.subarray(c * size, (c + 1) * size)).join();
      if (!firstUse.has(id)) {
        firstUse.set(id, firstUse.size + 1);
        objLines.push(`${key} ${entry.text.join(' ')}`);
      }
      faceRefs[c].push(firstUse.get(id));
    });
    arrays[key] = values;
  }
  for (let c = 0; c < numCorners; c += 3) {
    objLines.push('f ' + [0, 1, 2].map((k) => faceRefs[c + k].join('/'))
        .join(' '));
  }
  return {arrays, numCorners, objText: objLines.join('\n') + '\n'};
}

function buildMesh(encoderModule, prepared) {
  const mesh = new encoderModule.Mesh();
  const builder = new encoderModule.MeshBuilder();
  const faces = new Int32Array(prepared.numCorners);
  faces.forEach((_, i) => faces[i] = i);
  builder.AddFacesToMesh(mesh, prepared.numCorners / 3, faces);
  const types = {v: encoderModule.POSITION, vt: encoderModule.TEX_COORD,
                 vn: encoderModule.NORMAL};
  for (const key of ['v', 'vt', 'vn']) {
    if (prepared.arrays[key]) {
      const size = key === 'vt' ? 2 : 3;
      builder.AddFloatAttribute(mesh, types[key], prepared.numCorners, size,
                                prepared.arrays[key]);
    }
  }
  encoderModule.destroy(builder);
  return mesh;
}

function setUpLikeDracoEncoder(encoderModule, encoder) {
  encoder.SetAttributeQuantization(encoderModule.POSITION, kQp);
  encoder.SetAttributeQuantization(encoderModule.TEX_COORD, kQt);
  encoder.SetAttributeQuantization(encoderModule.NORMAL, kQn);
  encoder.SetSpeedOptions(10 - kCl, 10 - kCl);
}

function bytesOf(encoderModule, array) {
  const bytes = new Uint8Array(array.size());
  for (let i = 0; i < bytes.length; ++i) bytes[i] = array.GetValue(i);
  return Buffer.from(bytes.buffer);
}

// Encodes |prepared| with a JS Encoder; |configure(encoder)| sets it up
// further. Returns the bytes (null on failure) and what the encoder says.
function encodeWithEncoder(encoderModule, prepared, configure) {
  const mesh = buildMesh(encoderModule, prepared);
  const encoder = new encoderModule.Encoder();
  const array = new encoderModule.DracoInt8Array();
  try {
    setUpLikeDracoEncoder(encoderModule, encoder);
    if (configure) configure(encoder);
    const size = encoder.EncodeMeshToDracoBuffer(mesh, array);
    return {bytes: size > 0 ? bytesOf(encoderModule, array) : null,
            used: encoder.UsedDracoUvCoding(),
            message: encoder.GetUvCompressionMessage()};
  } finally {
    encoderModule.destroy(array);
    encoderModule.destroy(encoder);
    encoderModule.destroy(mesh);
  }
}

// The same through an ExpertEncoder with |options| on the TEX_COORD
// attribute by id.
function encodeWithExpert(encoderModule, prepared, options) {
  const mesh = buildMesh(encoderModule, prepared);
  const encoder = new encoderModule.ExpertEncoder(mesh);
  const array = new encoderModule.DracoInt8Array();
  try {
    const ids = {pos: 0, uv: 1, normal: 2};
    encoder.SetAttributeQuantization(ids.pos, kQp);
    encoder.SetAttributeQuantization(ids.uv, kQt);
    if (prepared.arrays.vn) encoder.SetAttributeQuantization(ids.normal, kQn);
    encoder.SetSpeedOptions(10 - kCl, 10 - kCl);
    check(!encoder.SetAttributeUvCompression(ids.pos, options),
          'ExpertEncoder.SetAttributeUvCompression accepts POSITION');
    check(encoder.SetAttributeUvCompression(ids.uv, options),
          `ExpertEncoder.SetAttributeUvCompression: ` +
          encoder.GetUvCompressionMessage());
    const size = encoder.EncodeToDracoBuffer(true, array);
    return {bytes: size > 0 ? bytesOf(encoderModule, array) : null,
            used: encoder.UsedDracoUvCoding(),
            message: encoder.GetUvCompressionMessage()};
  } finally {
    encoderModule.destroy(array);
    encoderModule.destroy(encoder);
    encoderModule.destroy(mesh);
  }
}

// Positions and texture coordinates at every face corner, quantized (the
// decoder skips the attributes' transforms), as one string per attribute.
function quantizedCorners(decoderModule, bytes) {
  const decoder = new decoderModule.Decoder();
  const mesh = new decoderModule.Mesh();
  try {
    decoder.SkipAttributeTransform(decoderModule.POSITION);
    decoder.SkipAttributeTransform(decoderModule.TEX_COORD);
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    if (!status.ok()) throw new Error(status.error_msg());
    const result = {faces: mesh.num_faces()};
    const face = new decoderModule.DracoInt32Array();
    for (const [name, type] of [['pos', decoderModule.POSITION],
                                ['uv', decoderModule.TEX_COORD]]) {
      const att = decoder.GetAttribute(
          mesh, decoder.GetAttributeId(mesh, type));
      const values = new decoderModule.DracoInt32Array();
      decoder.GetAttributeInt32ForAllPoints(mesh, att, values);
      const n = att.num_components();
      const corners = [];
      for (let f = 0; f < mesh.num_faces(); ++f) {
        decoder.GetFaceFromMesh(mesh, f, face);
        for (let k = 0; k < 3; ++k) {
          const p = face.GetValue(k);
          for (let i = 0; i < n; ++i) corners.push(values.GetValue(p * n + i));
        }
      }
      decoderModule.destroy(values);
      result[name] = corners.join(',');
    }
    decoderModule.destroy(face);
    return result;
  } finally {
    decoderModule.destroy(mesh);
    decoderModule.destroy(decoder);
  }
}

// The error of npm draco3d's decoder on |bytes|, or null if it decodes.
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

function nativeEncode(encoderPath, objFile, outFile, flags) {
  execFileSync(encoderPath, ['-i', objFile, '-o', outFile, '-qp', `${kQp}`,
                             '-qt', `${kQt}`, '-qn', `${kQn}`, '-cl',
                             `${kCl}`].concat(flags), {stdio: 'pipe'});
  return fs.readFileSync(outFile);
}

function uvFlags(setting) {
  return (setting.prediction ? ['-uv_pred', setting.prediction] : [])
      .concat(setting.seams ? ['-uv_seams', setting.seams] : []);
}

function makeOptions(draco, setting) {
  return draco.createUvOptions(draco.encoderModule, setting);
}

// Unknown names and inconsistent options, through the IDL and draco3d.js.
async function checkErrors(draco, encoderModule) {
  const options = new encoderModule.DracoUvOptions();
  check(!options.SetPrediction('wieghted'), 'SetPrediction accepts wieghted');
  const message = options.GetErrorMessage();
  for (const name of ['auto', 'weighted_multi', 'laplacian_mv']) {
    check(message.includes(name),
          `SetPrediction's message lacks ${name}: ${message}`);
  }
  check(!options.SetSeams('contxt'), 'SetSeams accepts contxt');
  check(options.GetErrorMessage().includes('context'),
        `SetSeams's message: ${options.GetErrorMessage()}`);
  check(!options.SetAnchors('many'), 'SetAnchors accepts many');
  // Anchors with a prediction that is not Laplacian: refused where applied.
  check(options.SetPrediction('weighted') && options.SetAnchors('50'),
        'weighted with 50 anchors cannot be set');
  const encoder = new encoderModule.Encoder();
  check(!encoder.SetAttributeUvCompression(encoderModule.TEX_COORD, options),
        'Encoder accepts anchors with weighted');
  check(encoder.GetUvCompressionMessage().includes('-uv_anchors'),
        `Encoder's message: ${encoder.GetUvCompressionMessage()}`);
  check(!encoder.SetAttributeUvCompression(encoderModule.POSITION,
                                           new encoderModule.DracoUvOptions()),
        'Encoder accepts POSITION');
  const uvModule = new encoderModule.DracoUvModule();
  check(!uvModule.SetDefault(options), 'SetDefault accepts anchors with ' +
        'weighted');
  check(uvModule.GetErrorMessage().includes('-uv_anchors'),
        `DracoUvModule's message: ${uvModule.GetErrorMessage()}`);
  encoderModule.destroy(uvModule);
  encoderModule.destroy(encoder);
  encoderModule.destroy(options);

  let thrown = null;
  try {
    draco.createUvOptions(encoderModule, {prediction: 'wieghted'});
  } catch (error) {
    thrown = error;
  }
  check(thrown instanceof Error && thrown.message.includes('weighted_multi'),
        `createUvOptions: ${thrown}`);
  for (const settings of [{prediction: 'wieghted'}, {seams: 'contxt'},
                          {prediction: 'auto', anchors: '10'}]) {
    let rejected = null;
    await draco.createEncoderModule({texCoordCompression: settings})
        .catch((error) => rejected = error);
    check(rejected instanceof Error && rejected.message.length > 0,
          `createEncoderModule(${JSON.stringify(settings)}) resolved`);
    console.log(`rejected ${JSON.stringify(settings)}: ${rejected &&
        rejected.message.split('\n')[0]}`);
  }
}

async function main() {
  const packageDir = process.env.DRACO_UV_WEB_PACKAGE;
  const buildDir = process.env.DRACO_UV_BUILD_DIR;
  const sourceDir = process.env.DRACO_UV_SOURCE_DIR ||
      path.join(__dirname, '..', '..');
  const testdata = process.env.DRACO_TESTDATA || path.join(
      sourceDir, 'third_party', 'debian-draco-1.5.5+dfsg-2', 'testdata');
  if (!packageDir || !fs.existsSync(path.join(packageDir, 'draco3d.js'))) {
    skip('DRACO_UV_WEB_PACKAGE is not a built web package');
  }
  const encoderPath = buildDir && path.join(buildDir, 'draco', 'draco_encoder');
  if (!encoderPath || !fs.existsSync(encoderPath)) {
    skip('no native draco_encoder in DRACO_UV_BUILD_DIR');
  }
  let stockDraco;
  try {
    stockDraco = require('draco3d');
  } catch (error) {
    skip('npm draco3d is not installed (tests/web/install-packages.sh)');
  }
  const draco = require(path.resolve(packageDir, 'draco3d.js'));
  const encoderModule = await draco.createEncoderModule({});
  draco.encoderModule = encoderModule;
  const decoderModule = await draco.createDecoderModule({});
  const stockModule = await stockDraco.createDecoderModule({});
  if (!encoderModule.DracoUvOptions) {
    throw new Error('the package\'s encoder has no DracoUvOptions');
  }
  await checkErrors(draco, encoderModule);

  const meshes = ['crane_spot.obj', 'torus_uv.obj', 'bumpy_cube_sphere.obj']
      .map((name) => path.join(sourceDir, 'testdata', name))
      .concat([path.join(testdata, 'cube_att.obj')]);
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'encoder_api_test-'));
  const totals = {stock: 0};
  const uvModule = new encoderModule.DracoUvModule();
  let expectedCount = uvModule.GetNumEncodesWithDracoUvIds();
  try {
    for (const file of meshes) {
      const prepared = prepareMesh(readObj(file));
      const objFile = path.join(tmp, 'mesh.obj');
      fs.writeFileSync(objFile, prepared.objText);
      const outFile = path.join(tmp, 'out.drc');
      const base = path.basename(file);

      const stock = encodeWithEncoder(encoderModule, prepared, null);
      check(stock.bytes !== null, `${base}: stock encode failed`);
      check(!stock.used && stock.message === '',
            `${base}: stock encode says ${stock.used} "${stock.message}"`);
      check(stock.bytes.equals(nativeEncode(encoderPath, objFile, outFile,
                                            [])),
            `${base}: stock bytes differ from draco_encoder's`);
      check(stockDecodeError(stockModule, stock.bytes) === null,
            `${base}: npm draco3d fails on the stock encode`);
      const stockCorners = quantizedCorners(decoderModule, stock.bytes);
      totals.stock += stock.bytes.length;

      for (const setting of kSettings) {
        const label = `${base} ${setting.name}`;
        const options = makeOptions(draco, setting);
        const result = encodeWithEncoder(encoderModule, prepared,
            (encoder) => check(encoder.SetAttributeUvCompression(
                encoderModule.TEX_COORD, options), `${label}: refused`));
        if (result.bytes === null) {
          check(false, `${label}: encode failed: ${result.message}`);
          encoderModule.destroy(options);
          continue;
        }
        const native = nativeEncode(encoderPath, objFile, outFile,
                                    uvFlags(setting));
        check(result.bytes.equals(native),
              `${label}: ${result.bytes.length} bytes, draco_encoder ` +
              `${native.length}`);
        const expert = encodeWithExpert(encoderModule, prepared, options);
        check(expert.bytes !== null && expert.bytes.equals(result.bytes),
              `${label}: ExpertEncoder wrote other bytes: ${expert.message}`);
        encoderModule.destroy(options);

        const stockError = stockDecodeError(stockModule, result.bytes);
        check(result.used === (stockError !== null),
              `${label}: UsedDracoUvCoding ${result.used}, npm draco3d ` +
              `error: ${stockError}`);
        expectedCount += (result.used ? 1 : 0) + (expert.used ? 1 : 0);
        const decoded = quantizedCorners(decoderModule, result.bytes);
        check(decoded.faces === stockCorners.faces, `${label}: faces`);
        check(decoded.pos === stockCorners.pos, `${label}: positions differ`);
        if (setting.lossless) {
          check(decoded.uv === stockCorners.uv, `${label}: UVs differ`);
        }
        if (setting.prediction === 'auto') {
          check(result.bytes.length <= stock.bytes.length &&
                (!result.used || result.bytes.length < stock.bytes.length),
                `${label}: ${result.bytes.length} bytes, stock ` +
                `${stock.bytes.length}, draco-uv ids ${result.used}`);
        }
        totals[setting.name] = (totals[setting.name] || 0) +
            result.bytes.length;
        console.log(`${label}: ${result.bytes.length} bytes (stock ` +
                    `${stock.bytes.length}), draco-uv ids ${result.used}, ` +
                    `npm draco3d: ${stockError || 'decodes'}`);
      }
    }
    for (const setting of kSettings) {
      check(totals[setting.name] < totals.stock,
            `${setting.name}: ${totals[setting.name]} bytes in all, stock ` +
            `${totals.stock}`);
    }
    check(uvModule.GetNumEncodesWithDracoUvIds() === expectedCount,
          `GetNumEncodesWithDracoUvIds ${uvModule.GetNumEncodesWithDracoUvIds()}` +
          `, expected ${expectedCount}`);
    await checkModuleDefault(draco, encoderModule, meshes, tmp, encoderPath);
    await checkGltfWrite(draco, meshes);
  } finally {
    encoderModule.destroy(uvModule);
    fs.rmSync(tmp, {recursive: true, force: true});
  }
  console.log(failures === 0 ? 'encoder_api: passed' :
                               `encoder_api: ${failures} failure(s)`);
  process.exit(failures === 0 ? 0 : 1);
}

// createEncoderModule({texCoordCompression}) sets a default that every
// Encoder without its own setting uses; an own setting ("" prediction:
// Draco's) overrides it; ClearDefault() returns to stock coding.
async function checkModuleDefault(draco, _, meshes, tmp, encoderPath) {
  const setting = {prediction: 'weighted', seams: 'context'};
  const encoderModule =
      await draco.createEncoderModule({texCoordCompression: setting});
  const uvModule = new encoderModule.DracoUvModule();
  const objFile = path.join(tmp, 'mesh.obj');
  const outFile = path.join(tmp, 'out.drc');
  for (const file of meshes.slice(1, 3)) {
    const prepared = prepareMesh(readObj(file));
    fs.writeFileSync(objFile, prepared.objText);
    const base = `${path.basename(file)} module default`;
    const before = uvModule.GetNumEncodesWithDracoUvIds();
    const result = encodeWithEncoder(encoderModule, prepared, null);
    check(result.bytes !== null && result.used,
          `${base}: ${result.message}`);
    check(result.bytes.equals(nativeEncode(encoderPath, objFile, outFile,
                                           uvFlags(setting))),
          `${base}: bytes differ from draco_encoder's`);
    check(uvModule.GetNumEncodesWithDracoUvIds() === before + 1,
          `${base}: count ${uvModule.GetNumEncodesWithDracoUvIds()}`);
    const stockBytes = nativeEncode(encoderPath, objFile, outFile, []);
    const own = draco.createUvOptions(encoderModule, {prediction: ''});
    const overridden = encodeWithEncoder(encoderModule, prepared,
        (encoder) => encoder.SetAttributeUvCompression(
            encoderModule.TEX_COORD, own));
    encoderModule.destroy(own);
    check(overridden.bytes.equals(stockBytes) && !overridden.used,
          `${base}: an own stock setting does not override the default`);
    uvModule.ClearDefault();
    const cleared = encodeWithEncoder(encoderModule, prepared, null);
    check(cleared.bytes.equals(stockBytes) && !cleared.used,
          `${base}: ClearDefault() does not restore stock coding`);
    draco.setUvDefault(encoderModule, setting);
    console.log(`${base}: ${result.bytes.length} bytes, stock ` +
                `${stockBytes.length}`);
  }
  encoderModule.destroy(uvModule);
}

// auto in glTF writes: the native glTF encoder's rule (draco_ext/gltf/
// uv_gltf.h, KeepDracoUvOnlyIfItPaysForTheExtension) through WebAssembly.
async function checkGltfWrite(draco, meshes) {
  const kMarkerBytes = 76;  // kUvGltfExtensionJsonBytes
  const encoderModule = await draco.createEncoderModule(
      {texCoordCompression: {prediction: 'auto'}});
  const uvModule = new encoderModule.DracoUvModule();
  const stockOptions = draco.createUvOptions(encoderModule, {});
  const encode = (prepared) => encodeWithEncoder(encoderModule, prepared,
                                                 null);
  // The meshes, and pieces of them (their first triangles), on some of
  // which draco-uv saves less than the marker costs (crane_spot's first 600
  // triangles: 61 bytes).
  const pieces = [];
  for (const file of meshes) {
    const obj = readObj(file);
    pieces.push({base: path.basename(file), obj});
    for (const triangles of [150, 600].filter(
        (t) => 3 * t < obj.corners.length)) {
      const corners = obj.corners.slice(0, 3 * triangles);
      pieces.push({base: `${path.basename(file)}[${triangles} triangles]`,
                   obj: {...obj, corners}});
    }
  }
  const cases = pieces.map(({base, obj}) => {
    const prepared = prepareMesh(obj);
    const auto = encode(prepared);
    const stock = encodeWithEncoder(encoderModule, prepared,
        (encoder) => encoder.SetAttributeUvCompression(
            encoderModule.TEX_COORD, stockOptions));
    return {base, prepared, auto, stock,
            pays: auto.used &&
                  auto.bytes.length + kMarkerBytes < stock.bytes.length};
  });
  encoderModule.destroy(stockOptions);
  for (const c of cases) {
    uvModule.BeginGltfWrite();
    const first = encode(c.prepared);
    uvModule.EndGltfWrite();
    const dropsIds = c.auto.used && !c.pays;
    check(first.bytes.equals(dropsIds ? c.stock.bytes : c.auto.bytes) &&
          first.used === c.pays,
          `${c.base} glTF write: ${first.bytes.length} bytes, auto ` +
          `${c.auto.bytes.length}, stock ${c.stock.bytes.length}`);
    check(!dropsIds || first.message.includes('DRACOUV_attribute_compression'),
          `${c.base} glTF write: message "${first.message}"`);
    console.log(`${c.base} glTF write: ${first.bytes.length} bytes (auto ` +
                `${c.auto.bytes.length}${c.auto.used ? ' with ids' : ''}, ` +
                `stock ${c.stock.bytes.length})`);
  }
  const paying = cases.find((c) => c.pays);
  const dropped = cases.filter((c) => c.auto.used && !c.pays);
  check(paying && dropped.length > 0,
        'glTF write: the meshes do not cover both outcomes');
  if (paying) {
    uvModule.BeginGltfWrite();
    encode(paying.prepared);
    for (const c of dropped) {
      const later = encode(c.prepared);
      check(later.bytes.equals(c.auto.bytes) && later.used,
            `${c.base}: a later encode of the glTF write did not keep ` +
            'auto\'s choice');
    }
    uvModule.EndGltfWrite();
  }
  for (const c of dropped) {
    check(encode(c.prepared).bytes.equals(c.auto.bytes),
          `${c.base}: after EndGltfWrite auto is not the plain auto`);
  }
  encoderModule.destroy(uvModule);
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
