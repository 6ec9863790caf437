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
 * The package's default decoder and its Laplacian part,
 * draco_decoder_laplacian.wasm, in Node.js:
 *  - through createDecoderModule (draco3d.js), lossless golden files decode
 *    without looking the part up (counted through the module's locateFile);
 *    the first Laplacian file looks it up once, later ones reuse it; every
 *    lossy golden file decodes to the values of the package's asm.js
 *    decoder, which has every coder in one file;
 *  - loadDracoUvLaplacian() resolves, and a module given the part's bytes
 *    (dracoUvLaplacianWasm) decodes without looking anything up;
 *  - the part's C interface on hostile input: faces out of range, negative
 *    counts and random streams over a real texture mesh return -1 or finite
 *    values, never trap, and the part's memory stays under 64 MB.
 *
 *   node tests/web/laplacian_part_test.js
 *
 * Environment (tests/web contract): DRACO_UV_WEB_PACKAGE; DRACO_UV_SOURCE_DIR
 * for testdata/golden (default: this checkout).
 */
'use strict';

const fs = require('fs');
const path = require('path');

const kPart = 'draco_decoder_laplacian.wasm';
const kMaxPartBytes = 64 * 1024 * 1024;

let failures = 0;
function check(ok, what) {
  if (!ok) {
    console.log(`FAIL: ${what}`);
    ++failures;
  }
  return ok;
}

/** Decodes a mesh; returns its TEX_COORD values (quantized) or throws. */
function texCoords(draco, bytes) {
  const decoder = new draco.Decoder();
  const mesh = new draco.Mesh();
  try {
    decoder.SkipAttributeTransform(draco.TEX_COORD);
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    if (!status.ok()) throw new Error(status.error_msg());
    const id = decoder.GetAttributeId(mesh, draco.TEX_COORD);
    const attribute = decoder.GetAttribute(mesh, id);
    const values = new draco.DracoInt32Array();
    decoder.GetAttributeInt32ForAllPoints(mesh, attribute, values);
    const out = Array.from({length: values.size()}, (_, i) => values.GetValue(i));
    draco.destroy(values);
    return out;
  } finally {
    draco.destroy(mesh);
    draco.destroy(decoder);
  }
}

async function checkOnDemand(packageDir, goldenDir) {
  const {createDecoderModule} = require(path.join(packageDir, 'draco3d.js'));
  const lookups = [];
  const draco = await createDecoderModule({
    locateFile: (name, folder) => {
      if (name === kPart) lookups.push(name);
      return folder + name;
    }});
  const reference = await require(path.join(packageDir, 'draco_decoder.js'))();
  const lossless = fs.readdirSync(goldenDir).filter((f) => f.endsWith('.drc'));
  for (const file of lossless) {
    texCoords(draco, fs.readFileSync(path.join(goldenDir, file)));
  }
  check(lookups.length === 0, `${lossless.length} lossless files looked ` +
        `${kPart} up ${lookups.length} times`);
  const lossyDir = path.join(goldenDir, 'lossy');
  const lossy = fs.readdirSync(lossyDir).filter((f) => f.endsWith('.drc'));
  for (const file of lossy) {
    const bytes = fs.readFileSync(path.join(lossyDir, file));
    const got = texCoords(draco, bytes);
    const want = texCoords(reference, bytes);
    check(got.length > 0 && got.every((v, i) => v === want[i]),
          `lossy/${file}: the on-demand decoder differs from asm.js`);
  }
  check(lookups.length === 1, `${lossy.length} Laplacian files looked ` +
        `${kPart} up ${lookups.length} times (once expected)`);
  console.log(`on demand: ${lossless.length} lossless files, 0 lookups; ` +
              `${lossy.length} Laplacian files equal to asm.js, ` +
              `${lookups.length} lookup`);
  await draco.loadDracoUvLaplacian();

  const bytes = fs.readFileSync(path.join(packageDir, kPart));
  const given = await createDecoderModule({
    dracoUvLaplacianWasm: bytes,
    locateFile: (name, folder) => {
      check(name !== kPart, 'looked the part up despite its bytes');
      return folder + name;
    }});
  const file = path.join(lossyDir, lossy[0]);
  texCoords(given, fs.readFileSync(file));
  console.log('given its bytes: decodes without a lookup');
}

/** A w x h grid of texture vertices, two triangles per cell. */
function grid(w, h) {
  const positions = [];
  const faces = [];
  for (let y = 0; y < h; ++y) {
    for (let x = 0; x < w; ++x) positions.push(x, y, (x * y) % 7);
  }
  for (let y = 0; y + 1 < h; ++y) {
    for (let x = 0; x + 1 < w; ++x) {
      const v = y * w + x;
      faces.push(v, v + 1, v + w, v + 1, v + w + 1, v + w);
    }
  }
  return {positions, faces, numVertices: w * h, numFaces: faces.length / 3};
}

function makeRandom(seed) {
  let a = seed >>> 0;
  return () => {  // mulberry32
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Calls the part's C interface once in a fresh instance. */
function callPart(module, mesh, stream, counts = {}) {
  const part = new WebAssembly.Instance(module, {
    env: {emscripten_notify_memory_growth() {}},
    wasi_snapshot_preview1: {proc_exit() { throw new Error('proc_exit'); }},
  }).exports;
  part._initialize();
  const put = (Type, values) => {
    const ptr = part.malloc(values.length * Type.BYTES_PER_ELEMENT || 1);
    new Type(part.memory.buffer, ptr, values.length).set(values);
    return ptr;
  };
  const positions = put(Float64Array, mesh.positions);
  const faces = put(Int32Array, mesh.faces);
  const bytes = put(Uint8Array, stream);
  const out = part.malloc(16 * mesh.numVertices || 1);
  const bits = part.draco_uv_laplacian_decode(
      positions, counts.numVertices ?? mesh.numVertices, faces,
      counts.numFaces ?? mesh.numFaces, bytes, stream.length, 0x202, out);
  const uv = bits >= 0 ?
      Array.from(new Float64Array(part.memory.buffer, out,
                                  2 * mesh.numVertices)) : [];
  return {bits, uv, memory: part.memory.buffer.byteLength};
}

function checkPartInterface(packageDir) {
  const module = new WebAssembly.Module(
      fs.readFileSync(path.join(packageDir, kPart)));
  const mesh = grid(20, 20);
  const random = makeRandom(37);
  const stream = Uint8Array.from({length: 400}, () => (random() * 256) | 0);
  const badFace = {...mesh, faces: mesh.faces.slice()};
  badFace.faces[7] = mesh.numVertices;
  check(callPart(module, badFace, stream).bits === -1,
        'a face vertex out of range is accepted');
  check(callPart(module, mesh, stream, {numVertices: -1}).bits === -1,
        'a negative vertex count is accepted');
  check(callPart(module, mesh, stream, {numFaces: -3}).bits === -1,
        'a negative face count is accepted');
  let decoded = 0;
  let maxMemory = 0;
  for (let i = 0; i < 300; ++i) {
    const bytes = stream.map(() => (random() * 256) | 0);
    // Plausible headers too: operator kind, step and frame bits.
    if (i % 2) bytes.set([i % 3, 1 + (i % 12), 12 + (i % 8)]);
    let result;
    try {
      result = callPart(module, mesh, bytes.subarray(0, 3 + (i % 397)));
    } catch (error) {
      check(false, `random stream ${i} trapped: ${error.message}`);
      continue;
    }
    maxMemory = Math.max(maxMemory, result.memory);
    if (result.bits >= 0) {
      ++decoded;
      check(result.uv.every(Number.isFinite),
            `random stream ${i} decoded to non-finite values`);
    }
  }
  check(maxMemory <= kMaxPartBytes, `the part grew to ${maxMemory} bytes`);
  console.log(`part interface: bad faces and counts refused; 300 random ` +
              `streams: ${decoded} decode to finite values, the rest ` +
              `refused, at most ${maxMemory / 1048576} MB`);
}

async function main() {
  const packageDir = path.resolve(process.env.DRACO_UV_WEB_PACKAGE || '');
  if (!fs.existsSync(path.join(packageDir, kPart))) {
    console.error(`laplacian_part_test: no ${kPart} in ${packageDir} ` +
                  '(DRACO_UV_WEB_PACKAGE; ./draco-uv.sh web builds it)');
    process.exit(1);
  }
  const source = process.env.DRACO_UV_SOURCE_DIR ||
      path.join(__dirname, '..', '..');
  await checkOnDemand(packageDir, path.join(source, 'testdata', 'golden'));
  checkPartInterface(packageDir);
  console.log(`laplacian_part_test: ${failures} failures`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(`FAIL: ${error.stack || error}`);
  process.exit(1);
});
