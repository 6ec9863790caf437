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

// Decodes every golden file with a JavaScript/WebAssembly Draco decoder
// (the draco-uv web build, scripts/build-web.sh) and compares what it
// decodes to with testdata/golden/expected.tsv, which the native decoder
// wrote (scripts/make-golden.sh). The digest is draco_uv_digest's
// (draco_ext/eval/uv_decoded_digest.h), computed here in JavaScript from
// the decoder's JS API:
//
//   "faces=F points=P" and, per attribute in id order,
//   " TYPE:DATATYPExN=HASH", HASH being the FNV-1a (64 bit) of the
//   attribute's values (little-endian bytes of its data type) at every face
//   corner in face order, with Draco's attribute transforms skipped
//   (Decoder.SkipAttributeTransform), so the quantized integers the
//   bitstream codes are compared and no floating point arithmetic.
//
// The tangent golden files (testdata/golden/tangent_variants.tsv's rows on
// the *_tangents meshes) are rows of expected.tsv too; beyond their digests,
// every row of tangent_variants.tsv must have a golden file of each tangent
// mesh, and each tangent prediction's file must decode to the tangents
// (GENERIC) of stock coding at the same -qtg (tangent_draco_qtgN), as the
// prediction is lossless.
//
// The lossy Laplacian golden files (testdata/golden/lossy/) have no expected
// values (their decoded floats may differ between builds); each must decode,
// and its digests (quantized, and dequantized as draco_uv_digest
// --dequantized prints it) are printed for comparisons by hand.
//
//   node tests/web/check_golden.js [--without-laplacian] MODULE.js [GOLDEN_DIR]
//
// --without-laplacian is for a decoder built without the Laplacian coder
// (-DDRACO_UV_LAPLACIAN=OFF): there every lossy file must fail with a
// decoder error instead of decoding. --without-laplacian-part is for the
// package's default decoder, whose Laplacian part loads on demand: given a
// folder without the part (option dracoUvPath), every lossy file must fail
// with a decoder error that names the part's file, and the module must go
// on decoding.
//
// MODULE.js is a decoder module that defines DracoDecoderModule, e.g.
// build-web/draco3d-uv/draco_wasm_wrapper.js (its .wasm is read from
// draco_decoder.wasm next to it), draco_decoder.js (asm.js) or
// gltf/draco_wasm_wrapper.js. Prints one line per file and a closing
// "golden: N passed, M failed"; exits 1 on any failure.
'use strict';

const fs = require('fs');
const path = require('path');

const kFnvOffset = 0xcbf29ce484222325n;
const kFnvPrime = 0x100000001b3n;
const kMask64 = 0xffffffffffffffffn;

// Names as in GeometryAttribute::TypeToString() and the digest's
// DataTypeName().
const kAttributeTypeNames = ['POSITION', 'NORMAL', 'COLOR', 'TEX_COORD',
                             'GENERIC'];
const kDataTypes = {
  // draco DataType: [name, bytes, typed array, decoder's DT_* constant]
  1: ['int8', 1, Int8Array],
  2: ['uint8', 1, Uint8Array],
  3: ['int16', 2, Int16Array],
  4: ['uint16', 2, Uint16Array],
  5: ['int32', 4, Int32Array],
  6: ['uint32', 4, Uint32Array],
  9: ['float32', 4, Float32Array],
};

function fnv1a64(bytes, hash) {
  for (let i = 0; i < bytes.length; ++i) {
    hash = ((hash ^ BigInt(bytes[i])) * kFnvPrime) & kMask64;
  }
  return hash;
}

// Loads the decoder module MODULE.js with draco_decoder.wasm next to it read
// from disk and passed as wasmBinary: the glue of Debian's emscripten 3.1.6
// would try fetch() on a file path in Node 18+. An asm.js module ignores it.
async function loadDecoder(modulePath, options) {
  const factory = require(path.resolve(modulePath));
  const wasmPath = path.join(path.dirname(modulePath), 'draco_decoder.wasm');
  if (fs.existsSync(wasmPath)) options.wasmBinary = fs.readFileSync(wasmPath);
  return factory(options);
}

// The decoder's own error status (as opposed to a failure of this script or
// a trap in the module).
class DecodeError extends Error {}

// Returns the digest line of the mesh in |data| or throws with the
// decoder's error message. |dequantized|: with Draco's attribute transforms
// (draco_uv_digest --dequantized), i.e. the values a normal decode returns.
function digest(draco, data, dequantized = false) {
  const decoder = new draco.Decoder();
  const mesh = new draco.Mesh();
  try {
    for (const type of [draco.POSITION, draco.NORMAL, draco.COLOR,
                        draco.TEX_COORD, draco.GENERIC]) {
      if (!dequantized) decoder.SkipAttributeTransform(type);
    }
    const status = decoder.DecodeArrayToMesh(data, data.byteLength, mesh);
    if (!status.ok()) throw new DecodeError(status.error_msg());
    const numFaces = mesh.num_faces();
    const numPoints = mesh.num_points();
    const indexBytes = numFaces * 3 * 4;
    const indexPtr = draco._malloc(indexBytes);
    decoder.GetTrianglesUInt32Array(mesh, indexBytes, indexPtr);
    const faces = new Uint32Array(draco.HEAPU8.buffer, indexPtr,
                                  numFaces * 3).slice();
    draco._free(indexPtr);
    let line = `faces=${numFaces} points=${numPoints}`;
    for (let id = 0; id < mesh.num_attributes(); ++id) {
      const att = decoder.GetAttribute(mesh, id);
      const components = att.num_components();
      const type = kDataTypes[att.data_type()];
      if (!type) throw new Error(`attribute ${id}: data type ${att.data_type()}`);
      const [typeName, typeBytes, ArrayType] = type;
      const valueBytes = components * typeBytes;
      const size = numPoints * valueBytes;
      const ptr = draco._malloc(size);
      if (!decoder.GetAttributeDataArrayForAllPoints(mesh, att,
                                                     att.data_type(), size,
                                                     ptr)) {
        draco._free(ptr);
        throw new Error(`attribute ${id}: no values`);
      }
      // Little-endian bytes of every point's values, as the native digest
      // hashes them (WebAssembly memory is little-endian).
      const values = new Uint8Array(
          new ArrayType(draco.HEAPU8.buffer, ptr, numPoints * components)
              .slice().buffer);
      draco._free(ptr);
      let hash = kFnvOffset;
      for (const point of faces) {
        hash = fnv1a64(values.subarray(point * valueBytes,
                                       (point + 1) * valueBytes), hash);
      }
      line += ` ${kAttributeTypeNames[att.attribute_type()]}:${typeName}` +
              `x${components}=${hash.toString(16).padStart(16, '0')}`;
    }
    return line;
  } finally {
    draco.destroy(mesh);
    draco.destroy(decoder);
  }
}

// The tangent golden files' coverage and losslessness (above); |decoded|
// maps each file of expected.tsv to its decoded digest line. Returns the
// problems found.
function checkTangentFiles(goldenDir, decoded) {
  const variantsFile = path.join(goldenDir, 'tangent_variants.tsv');
  if (!fs.existsSync(variantsFile)) return [];
  const variants = fs.readFileSync(variantsFile, 'utf8').split('\n')
      .filter((line) => line && !line.startsWith('#'))
      .map((line) => line.split('\t')[0]);
  const meshes = new Set([...decoded.keys()]
      .filter((file) => /^[^.]*_tangents\./.test(file))
      .map((file) => file.split('.')[0]));
  const problems = [];
  if (meshes.size === 0) problems.push('no tangent golden files');
  const tangents = (line) => (/ GENERIC:\S+x4=(\S+)/.exec(line) || [])[1];
  for (const mesh of meshes) {
    for (const variant of variants) {
      const file = `${mesh}.${variant}.drc`;
      const stock = `${mesh}.${variant.replace(/^tangent_[a-z]+_/,
                                               'tangent_draco_')}.drc`;
      if (!decoded.has(file)) {
        problems.push(`${file}: tangent_variants.tsv row without a golden ` +
                      'file in expected.tsv');
      } else if (!tangents(decoded.get(file)) ||
                 tangents(decoded.get(file)) !==
                     tangents(decoded.get(stock) || '')) {
        problems.push(`${file}: tangents decode to ` +
                      `${tangents(decoded.get(file))}, stock coding's ` +
                      `(${stock}) to ${tangents(decoded.get(stock) || '')}`);
      }
    }
  }
  console.log(`tangent golden files: ${meshes.size} meshes x ` +
              `${variants.length} rows of tangent_variants.tsv checked`);
  return problems;
}

async function main() {
  const args = process.argv.slice(2);
  const without = ['--without-laplacian', '--without-laplacian-part']
      .includes(args[0]) ? args.shift() : '';
  const withoutLaplacian = without !== '';
  const [modulePath, goldenArg] = args;
  if (!modulePath) {
    console.error(
        'usage: node check_golden.js [--without-laplacian | ' +
        '--without-laplacian-part] MODULE.js [GOLDEN_DIR]');
    process.exit(2);
  }
  const goldenDir = goldenArg ||
      path.join(__dirname, '..', '..', 'testdata', 'golden');
  const draco = await loadDecoder(modulePath, without === '--without-laplacian-part' ?
      {dracoUvPath: path.join(goldenDir, 'no-laplacian-part-here')} : {});
  let passed = 0;
  let failed = 0;
  const expected = fs.readFileSync(path.join(goldenDir, 'expected.tsv'),
                                   'utf8').split('\n').filter(Boolean);
  const decoded = new Map();
  for (const row of expected) {
    const [file, want] = row.split('\t');
    let got;
    try {
      got = digest(draco, fs.readFileSync(path.join(goldenDir, file)));
    } catch (error) {
      got = `error: ${error.message}`;
    }
    decoded.set(file, got);
    if (got === want) {
      ++passed;
      console.log(`ok ${file}`);
    } else {
      ++failed;
      console.log(`FAIL ${file}\n  expected ${want}\n  decoded  ${got}`);
    }
  }
  for (const problem of checkTangentFiles(goldenDir, decoded)) {
    ++failed;
    console.log(`FAIL ${problem}`);
  }
  // Lossy files: decoding must succeed (the values are not pinned), or,
  // without the Laplacian coder, fail with an error.
  const lossyDir = path.join(goldenDir, 'lossy');
  const lossy = fs.existsSync(lossyDir) ?
      fs.readdirSync(lossyDir).filter((f) => f.endsWith('.drc')).sort() : [];
  for (const file of lossy) {
    let line;
    let error;
    try {
      const data = fs.readFileSync(path.join(lossyDir, file));
      line = digest(draco, data) + '\tdequantized: ' +
          digest(draco, data, true);
    } catch (e) {
      error = e;
    }
    const refused = error instanceof DecodeError &&
        (without !== '--without-laplacian-part' ||
         error.message.includes('draco_decoder_laplacian.wasm'));
    if (withoutLaplacian ? refused : !error) {
      ++passed;
      console.log(`ok lossy/${file}\t${error ? error.message : line}`);
    } else {
      ++failed;
      console.log(`FAIL lossy/${file}: ${error ? error.message : 'decoded'}`);
    }
  }
  if (without === '--without-laplacian-part') {
    // The module still decodes after the refusals.
    const [file, want] = expected[0].split('\t');
    const again = digest(draco, fs.readFileSync(path.join(goldenDir, file)));
    again === want ? ++passed : ++failed;
    console.log(`${again === want ? 'ok' : 'FAIL'} ${file} after the refusals`);
  }
  console.log(`golden: ${passed} passed, ${failed} failed`);
  process.exit(failed === 0 && passed > 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
