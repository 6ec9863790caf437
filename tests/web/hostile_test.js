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
 * @fileoverview Hostile input against the web package's WebAssembly decoder
 * (CTest web.hostile; the web test contract, tests/web/CMakeLists.txt).
 *
 * Every golden file (testdata/golden/*.drc and lossy/*.drc) is truncated at
 * every length up to 64 bytes and at 40 more points, and corrupted by random
 * single bit flips and bursts of 2-8 flips (a seeded PRNG: the same variants
 * on every run; DRACO_UV_HOSTILE_SEED picks others). Each variant goes
 * through the decoder as three.js's DRACOLoader drives it
 * (GetEncodedGeometryType, DecodeArrayToMesh / DecodeArrayToPointCloud,
 * then every attribute's values and the triangles copied out through
 * _malloc'd memory). It must decode or fail with an error status and a
 * message; an exception (a wasm RuntimeError, an abort, a thrown C++
 * exception) fails the test, and so does a decode that takes longer than
 * kMaxDecodeMs or never returns (a watchdog in the main thread ends the
 * worker that decodes), or memory that grows past kMaxHeapBytes. The
 * original golden files must decode, and decode the same again after all
 * variants (the module's state survives them).
 *
 * Crafted headers that claim huge counts (built from files the native
 * draco_encoder writes): meshes claiming 2^26..2^32-1 points, faces,
 * vertices or Edgebreaker symbols, and a sequential point cloud claiming
 * 2^26 points, must fail with an error status without growing memory. On
 * three of them stock Draco (1.5.5 to upstream main, npm draco3d too)
 * allocates for the claimed counts before it reads data that would
 * contradict them and aborts at the memory cap: the Edgebreaker meshes
 * claiming 2^26 and 2^28 vertices, faces and symbols (the corner table is
 * sized first) and the point cloud (every attribute is sized for the
 * points); patches/0014 makes both decoders refuse such counts first.
 *
 * The package's draco_decoder.wasm must declare a memory maximum of at most
 * kDocumentedCapBytes (CMakeLists.txt, -sMAXIMUM_MEMORY).
 *
 *   node tests/web/hostile_test.js
 *
 * Environment: DRACO_UV_WEB_PACKAGE (the package folder), DRACO_UV_BUILD_DIR
 * (for draco/draco_encoder), DRACO_UV_SOURCE_DIR (the repository; default:
 * two folders up). Exit 0 pass, 1 fail, 77 skip.
 */
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');
const {execFileSync} = require('child_process');
const {Worker, isMainThread, parentPort, workerData} =
    require('worker_threads');

// The decoder's memory cap as CMakeLists.txt sets it (-sMAXIMUM_MEMORY).
const kDocumentedCapBytes = 2 * 1024 * 1024 * 1024;
// Variants are corrupted copies of files of at most a few KB: their decodes
// stay far below the cap. 64 MB is four times emscripten's initial memory.
const kMaxHeapBytes = 64 * 1024 * 1024;
// A golden file decodes in a few ms; a corrupted one must not take long.
const kMaxDecodeMs = 5000;
// The watchdog: a decode that has not returned after this long hangs.
const kHangMs = 30000;
const kTruncationPrefix = 64;
const kTruncationPoints = 40;
const kSingleFlips = 60;
const kBurstFlips = 20;

function skip(why) {
  console.log(`SKIP: ${why}`);
  process.exit(77);
}

// mulberry32: a small seeded PRNG, so that every run makes the same
// variants.
function makeRandom(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function goldenFiles(sourceDir) {
  const files = [];
  for (const dir of ['testdata/golden', 'testdata/golden/lossy']) {
    const full = path.join(sourceDir, dir);
    for (const name of fs.readdirSync(full).sort()) {
      if (name.endsWith('.drc')) {
        files.push({name: path.join(dir, name),
                    bytes: fs.readFileSync(path.join(full, name))});
      }
    }
  }
  return files;
}

// Truncations and bit flips of every golden file.
function makeVariants(files, seed) {
  const random = makeRandom(seed);
  const variants = [];
  for (const {name, bytes} of files) {
    const base = path.basename(name, '.drc');
    const lengths = new Set();
    for (let n = 0; n < Math.min(kTruncationPrefix, bytes.length); ++n) {
      lengths.add(n);
    }
    for (let i = 1; i <= kTruncationPoints; ++i) {
      lengths.add(Math.floor(bytes.length * i / (kTruncationPoints + 1)));
    }
    lengths.add(bytes.length - 1);
    for (const n of [...lengths].sort((a, b) => a - b)) {
      variants.push({name: `${base} truncated to ${n}`,
                     bytes: bytes.subarray(0, n)});
    }
    for (let i = 0; i < kSingleFlips + kBurstFlips; ++i) {
      const flips = i < kSingleFlips ? 1 : 2 + Math.floor(random() * 7);
      const copy = Buffer.from(bytes);
      const bits = [];
      for (let f = 0; f < flips; ++f) {
        const bit = Math.floor(random() * bytes.length * 8);
        copy[bit >> 3] ^= 1 << (bit & 7);
        bits.push(bit);
      }
      variants.push({name: `${base} bits ${bits.join(',')} flipped`,
                     bytes: copy});
    }
  }
  return variants;
}

function writeVarint(value) {
  const out = [];
  while (value >= 0x80) {
    out.push((value % 0x80) | 0x80);
    value = Math.floor(value / 0x80);
  }
  out.push(value);
  return Buffer.from(out);
}

function readVarint(bytes, pos) {
  let value = 0;
  let scale = 1;
  for (;;) {
    const byte = bytes[pos++];
    value += (byte & 0x7f) * scale;
    if (!(byte & 0x80)) return [value, pos];
    scale *= 0x80;
  }
}

// bytes with the varints that start at `start` replaced by `values` (null
// keeps one); the rest of the file is unchanged.
function replaceVarints(bytes, start, values) {
  const parts = [bytes.subarray(0, start)];
  let pos = start;
  for (const value of values) {
    const [old, next] = readVarint(bytes, pos);
    parts.push(writeVarint(value === null ? old : value));
    pos = next;
  }
  parts.push(bytes.subarray(pos));
  return Buffer.concat(parts);
}

// Draco's header: "DRACO", version 2.2 (meshes) or 2.3 (point clouds),
// encoder type, method, 16-bit flags; then the connectivity's counts.
const kHeaderBytes = 11;

function checkHeader(bytes, type, method, what) {
  if (bytes.subarray(0, 5).toString() !== 'DRACO' || bytes[7] !== type ||
      bytes[8] !== method || bytes.readUInt16LE(9) !== 0) {
    throw new Error(`${what}: not the expected Draco header`);
  }
}

// Files whose headers claim huge counts: from a sequential mesh and a
// sequential point cloud that the native encoder writes of torus_uv.obj,
// and from the golden Edgebreaker file torus_uv.stock.drc.
function makeCraftedFiles(sourceDir, encoder, tempDir) {
  const obj = path.join(sourceDir, 'testdata', 'torus_uv.obj');
  const sequential = path.join(tempDir, 'sequential.drc');
  const pointCloud = path.join(tempDir, 'point_cloud.drc');
  execFileSync(encoder, ['-i', obj, '-o', sequential, '-cl', '0']);
  execFileSync(encoder, ['-i', obj, '-o', pointCloud, '-cl', '0',
                         '-point_cloud']);
  const seq = fs.readFileSync(sequential);
  checkHeader(seq, 1, 0, 'sequential mesh');
  const edgebreaker = fs.readFileSync(
      path.join(sourceDir, 'testdata', 'golden', 'torus_uv.stock.drc'));
  checkHeader(edgebreaker, 1, 1, 'torus_uv.stock.drc');
  const cloud = fs.readFileSync(pointCloud);
  checkHeader(cloud, 0, 0, 'point cloud');

  const files = [];
  for (const n of [2 ** 26, 2 ** 28, 2 ** 31, 2 ** 32 - 1]) {
    // Sequential: varint faces, varint points.
    files.push({name: `sequential mesh claiming ${n} points`,
                bytes: replaceVarints(seq, kHeaderBytes, [null, n])});
    files.push({name: `sequential mesh claiming ${n} faces`,
                bytes: replaceVarints(seq, kHeaderBytes, [n, null])});
    files.push({name: `sequential mesh claiming ${n} faces and points`,
                bytes: replaceVarints(seq, kHeaderBytes, [n, n])});
    // Edgebreaker: traversal byte, then varints vertices and faces, a byte,
    // varints symbols and split symbols.
    const eb = kHeaderBytes + 1;
    files.push({name: `Edgebreaker mesh claiming ${n} vertices`,
                bytes: replaceVarints(edgebreaker, eb, [n])});
    files.push({name: `Edgebreaker mesh claiming ${n} vertices and faces`,
                bytes: replaceVarints(edgebreaker, eb, [n, n])});
    const [, afterFaces] =
        readVarint(edgebreaker, readVarint(edgebreaker, eb)[1]);
    const withFaces = replaceVarints(edgebreaker, eb, [n, n]);
    const symbolsAt = afterFaces + (withFaces.length - edgebreaker.length) + 1;
    files.push({
      name: `Edgebreaker mesh claiming ${n} vertices, faces and symbols`,
      bytes: replaceVarints(withFaces, symbolsAt, [n])});
  }
  // Point cloud: int32 points after the header.
  const claimed = Buffer.from(cloud);
  claimed.writeUInt32LE(2 ** 26, kHeaderBytes);
  files.push({name: `point cloud claiming ${2 ** 26} points`, bytes: claimed});
  return files;
}

// The memory maximum the .wasm declares (its memory section, or an
// imported memory), in bytes; null when it declares none.
function wasmMemoryMaximum(wasm) {
  const limits = (pos) => {
    const flags = wasm[pos];
    const [, next] = readVarint(wasm, pos + 1);
    return flags & 1 ? readVarint(wasm, next)[0] * 65536 : null;
  };
  let pos = 8;
  while (pos < wasm.length) {
    const id = wasm[pos];
    const [size, body] = readVarint(wasm, pos + 1);
    if (id === 5) return limits(readVarint(wasm, body)[1]);
    if (id === 2) {
      let [count, p] = readVarint(wasm, body);
      for (; count > 0; --count) {
        for (let s = 0; s < 2; ++s) {  // module and field names
          const [length, q] = readVarint(wasm, p);
          p = q + length;
        }
        const kind = wasm[p++];
        if (kind === 2) return limits(p);
        if (kind === 1) {  // table: element type, then limits
          const flags = wasm[p + 1];
          p = readVarint(wasm, p + 2)[1];
          if (flags & 1) p = readVarint(wasm, p)[1];
        } else if (kind === 3) {  // global: value type, mutability
          p += 2;
        } else {  // function: type index; tag: attribute, type index
          p = readVarint(wasm, kind === 4 ? p + 1 : p)[1];
        }
      }
    }
    pos = body + size;
  }
  return null;
}

// ---------------------------------------------------------------------------
// Worker: decodes the variants it is given, reporting each before and after.

async function workerMain() {
  const {createDecoderModule} =
      require(path.join(workerData.packageDir, 'draco3d.js'));
  let draco = await createDecoderModule({});
  for (let i = 0; i < workerData.variants.length; ++i) {
    parentPort.postMessage({type: 'start', index: i});
    const bytes = new Int8Array(workerData.variants[i].bytes);
    const started = performance.now();
    let result;
    try {
      result = decode(draco, bytes);
    } catch (error) {
      result = {outcome: 'exception', message: String(error).slice(0, 300)};
      // An aborted module is not used again.
      parentPort.postMessage({type: 'result', index: i,
                              heap: draco.HEAP8.length,
                              ms: performance.now() - started, ...result});
      draco = await createDecoderModule({});
      continue;
    }
    parentPort.postMessage({type: 'result', index: i, heap: draco.HEAP8.length,
                            ms: performance.now() - started, ...result});
  }
}

// One decode as three.js's DRACOLoader does it: {outcome: 'decoded' with
// the counts | 'error' with the message}.
function decode(draco, bytes) {
  const decoder = new draco.Decoder();
  const type = decoder.GetEncodedGeometryType(bytes);
  let geometry;
  let status;
  if (type === draco.TRIANGULAR_MESH) {
    geometry = new draco.Mesh();
    status = decoder.DecodeArrayToMesh(bytes, bytes.length, geometry);
  } else if (type === draco.POINT_CLOUD) {
    geometry = new draco.PointCloud();
    status = decoder.DecodeArrayToPointCloud(bytes, bytes.length, geometry);
  } else {
    draco.destroy(decoder);
    return {outcome: 'error', message: 'unknown geometry type'};
  }
  let result;
  if (!status.ok() || geometry.ptr === 0) {
    result = {outcome: 'error', message: status.error_msg()};
  } else {
    result = {outcome: 'decoded', points: geometry.num_points(),
              faces: type === draco.TRIANGULAR_MESH ? geometry.num_faces() : 0,
              digest: copyOut(draco, decoder, geometry, type)};
  }
  draco.destroy(geometry);
  draco.destroy(decoder);
  return result;
}

// Copies every attribute's values (as float32) and the triangles into
// _malloc'd memory, as a viewer does; returns a checksum of them.
function copyOut(draco, decoder, geometry, type) {
  let sum = 0;
  const take = (bytes, fill, view) => {
    const ptr = draco._malloc(bytes);
    if (!fill(ptr)) {
      draco._free(ptr);
      return;
    }
    const values = new view(draco.HEAP8.buffer, ptr, bytes / view.BYTES_PER_ELEMENT);
    for (let i = 0; i < values.length; ++i) {
      sum = (sum * 31 + (Number.isFinite(values[i]) ? values[i] : 7)) % 1e9;
    }
    draco._free(ptr);
  };
  for (let id = 0; id < geometry.num_attributes(); ++id) {
    const attribute = decoder.GetAttribute(geometry, id);
    const count = geometry.num_points() * attribute.num_components();
    take(count * 4, (ptr) => decoder.GetAttributeDataArrayForAllPoints(
        geometry, attribute, draco.DT_FLOAT32, count * 4, ptr), Float32Array);
  }
  if (type === draco.TRIANGULAR_MESH) {
    const count = geometry.num_faces() * 3;
    take(count * 4, (ptr) => decoder.GetTrianglesUInt32Array(
        geometry, count * 4, ptr), Uint32Array);
  }
  return sum;
}

// ---------------------------------------------------------------------------
// Main thread: runs a list of variants in a worker under the watchdog.

function runInWorker(packageDir, variants) {
  return new Promise((resolve, reject) => {
    const results = new Array(variants.length);
    const worker = new Worker(__filename, {workerData: {
      packageDir, variants: variants.map((v) => ({bytes: v.bytes}))}});
    let timer = null;
    worker.on('message', (message) => {
      clearTimeout(timer);
      if (message.type === 'fatal') {
        reject(new Error(`the decoding worker failed: ${message.message}`));
      } else if (message.type === 'start') {
        timer = setTimeout(() => {
          worker.terminate();
          reject(new Error(`"${variants[message.index].name}" did not ` +
                           `finish decoding within ${kHangMs} ms (hang)`));
        }, kHangMs);
      } else {
        results[message.index] = message;
      }
    });
    worker.on('error', reject);
    worker.on('exit', () => {
      clearTimeout(timer);
      resolve(results);
    });
  });
}

async function main() {
  const packageDir = process.env.DRACO_UV_WEB_PACKAGE;
  if (!packageDir || !fs.existsSync(path.join(packageDir, 'draco3d.js'))) {
    skip(`no web package in ${packageDir} (scripts/build-web.sh builds it)`);
  }
  const sourceDir = process.env.DRACO_UV_SOURCE_DIR ||
      path.join(__dirname, '..', '..');
  const encoder = path.join(process.env.DRACO_UV_BUILD_DIR || '', 'draco',
                            'draco_encoder');
  if (!fs.existsSync(encoder)) {
    skip(`no native draco_encoder in DRACO_UV_BUILD_DIR (${encoder})`);
  }
  const seed = Number(process.env.DRACO_UV_HOSTILE_SEED || 24);
  const failures = [];
  const fail = (message) => {
    failures.push(message);
    if (failures.length <= 20) console.log(`FAIL: ${message}`);
  };

  const cap = wasmMemoryMaximum(
      fs.readFileSync(path.join(packageDir, 'draco_decoder.wasm')));
  console.log(`draco_decoder.wasm memory maximum: ` +
              `${cap === null ? 'none' : cap / 1048576 + ' MB'}`);
  if (cap === null || cap > kDocumentedCapBytes) {
    fail(`the decoder's memory maximum is not at most ` +
         `${kDocumentedCapBytes / 1048576} MB (CMakeLists.txt sets ` +
         '-sMAXIMUM_MEMORY; rebuild the package)');
  }

  const tempDir = fs.mkdtempSync(path.join(os.tmpdir(), 'draco-uv-hostile-'));
  let crafted;
  try {
    crafted = makeCraftedFiles(sourceDir, encoder, tempDir);
  } finally {
    fs.rmSync(tempDir, {recursive: true, force: true});
  }
  const originals = goldenFiles(sourceDir);
  const variants = makeVariants(originals, seed);
  const all = [...originals, ...variants, ...crafted, ...originals];
  const started = Date.now();
  const results = await runInWorker(packageDir, all);
  const seconds = (Date.now() - started) / 1000;

  const n = originals.length;
  const counts = {decoded: 0, error: 0, exception: 0};
  let maxHeap = 0;
  let slowest = {ms: 0, name: ''};
  all.forEach((variant, i) => {
    const result = results[i];
    if (!result) {
      fail(`"${variant.name}": no result`);
      return;
    }
    if (i >= n && i < n + variants.length) ++counts[result.outcome];
    maxHeap = Math.max(maxHeap, result.heap);
    if (result.ms > slowest.ms) slowest = {ms: result.ms, name: variant.name};
    if (result.outcome === 'exception') {
      fail(`"${variant.name}" threw instead of failing: ${result.message}`);
    } else if (result.outcome === 'error' && !result.message) {
      fail(`"${variant.name}" failed without an error message`);
    }
    if (result.ms > kMaxDecodeMs) {
      fail(`"${variant.name}" took ${result.ms.toFixed(0)} ms`);
    }
    if (result.heap > kMaxHeapBytes) {
      fail(`"${variant.name}" grew memory to ${result.heap / 1048576} MB`);
    }
  });
  // The originals decode, before and after everything else.
  originals.forEach((original, i) => {
    const before = results[i];
    const after = results[all.length - n + i];
    if (!before || before.outcome !== 'decoded') {
      fail(`golden file ${original.name} does not decode`);
    } else if (!after || after.outcome !== before.outcome ||
               after.digest !== before.digest || after.faces !== before.faces) {
      fail(`golden file ${original.name} decodes differently after the ` +
           'hostile variants');
    }
  });
  // Every crafted file fails with an error status (an exception, a slow
  // decode or grown memory failed above).
  const craftedResults = results.slice(n + variants.length,
                                       n + variants.length + crafted.length);
  crafted.forEach((file, i) => {
    const result = craftedResults[i];
    if (result && result.outcome !== 'error') {
      fail(`"${file.name}" was not refused (${result.outcome})`);
    }
  });
  const craftedMs = Math.max(...craftedResults.map((r) => r?.ms || 0));
  console.log(`${crafted.length} crafted files claiming huge counts ` +
              'refused with an error status: ' +
              `${[...new Set(craftedResults.map((r) => r?.message))]
                  .join(', ')} (slowest ${craftedMs.toFixed(1)} ms)`);

  console.log(`${variants.length} variants of ${n} golden files ` +
              `(seed ${seed}): ` +
              `variants ${counts.decoded} decoded, ${counts.error} failed ` +
              `with an error, ${counts.exception} threw; memory at most ` +
              `${maxHeap / 1048576} MB; slowest decode ` +
              `${slowest.ms.toFixed(1)} ms (${slowest.name}); ` +
              `${seconds.toFixed(1)} s`);
  if (failures.length > 0) {
    console.log(`hostile: ${failures.length} failures`);
    process.exit(1);
  }
  console.log('hostile: passed');
}

if (isMainThread) {
  main().catch((error) => {
    console.log(`FAIL: ${error.stack || error}`);
    process.exit(1);
  });
} else {
  workerMain().catch((error) => {
    parentPort.postMessage({type: 'fatal', message: String(error)});
    throw error;
  });
}
