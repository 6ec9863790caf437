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

// WebAssembly decode times in Node.js: draco-uv's decoder (the web package,
// build-web/draco3d-uv) against npm draco3d's, both loaded into this one
// process. For every mesh it times three kinds of decode, interleaved in each
// round:
//
//   draco3d on the stock-coded file      (the baseline a user has today)
//   ours on the stock-coded file         (what our build costs by itself)
//   ours on each draco-uv-coded file     (what each UV coder costs)
//
// A decode is what three.js's DRACOLoader does: a new Decoder,
// GetEncodedGeometryType, DecodeArrayToMesh, GetAttributeDataArrayForAllPoints
// as Float32 for POSITION, NORMAL, COLOR, TEX_COORD and GENERIC (a glTF's
// TANGENT) when present,
// GetTrianglesUInt32Array, copies out of the heap, destroy. The
// DecodeArrayToMesh call is also timed alone: its ratios between our files
// and the stock file are the WebAssembly analogue of the native instruction
// counts inside Decoder::DecodeMeshFromBuffer
// (scripts/decode-instructions.sh), without the attribute copies that dilute
// the whole decode's. Each file's time is the minimum over the timed rounds,
// after warm-up rounds; the order of the decodes rotates from round to
// round. Every decode is timed on two clocks: wall time, and the process's
// CPU time, which other processes on a busy machine do not inflate by
// preempting this one (run Node with --single-threaded so that V8's helper
// threads add none, and --expose-gc: a garbage collection runs before each
// decode, untimed). Before timing, every decode's
// output is checked: ours and draco3d must give the same arrays on the stock
// file, and a lossless UV coder the same values at every face corner as the
// stock file (a Laplacian file's, or an error target's ("rmse..." schemes,
// on another -qt grid), largest UV difference is printed instead).
//
//   node --expose-gc --single-threaded benchmarks/web_decode_bench.js \
//       [options] INDEX.tsv
//
// INDEX.tsv (written by scripts/web-decode-bench.sh) has the header
// "mesh kind uv_vertices scheme file bytes", one row per encoded file; the
// scheme "stock" is the stock-coded file and must be present for each mesh.
// Options:
//   --ours DIR       our package folder (default build-web/draco3d-uv)
//   --draco3d DIR    npm draco3d's folder
//                    (default tests/web/node_modules/draco3d)
//   --rounds N       timed rounds per mesh (default 15)
//   --warmup N       untimed rounds first (default 3)
//   --clock cpu|wall the clock of the per-mesh tables (default cpu; the
//                    summary gives both)
//   --tsv FILE       also write every file's minimum and median times as TSV
// Prints Markdown: per-scheme medians (both clocks) with the worst mesh,
// per-kind medians, per-mesh tables, and the rounds' spread as a noise
// indicator.
'use strict';

const fs = require('fs');
const path = require('path');
const {performance} = require('perf_hooks');

const kRoot = path.join(__dirname, '..');
// GENERIC: glTF's TANGENT (and other glTF attributes) reach Draco as GENERIC,
// and DRACOLoader copies every attribute the glTF names.
const kAttributeTypes = ['POSITION', 'NORMAL', 'COLOR', 'TEX_COORD',
                         'GENERIC'];
const kTarget = 1.10;
const kClockNames = {
  wall: 'wall time',
  cpu: 'CPU time',
  callWall: 'DecodeArrayToMesh wall time',
  callCpu: 'DecodeArrayToMesh CPU time',
};

function parseArgs(argv) {
  const args = {
    ours: path.join(kRoot, 'build-web', 'draco3d-uv'),
    draco3d: path.join(kRoot, 'tests', 'web', 'node_modules', 'draco3d'),
    rounds: 15,
    warmup: 3,
    tsv: null,
    clock: 'cpu',
    index: null,
  };
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(`${arg} needs a value`);
      return argv[++i];
    };
    if (arg === '--ours') args.ours = path.resolve(value());
    else if (arg === '--draco3d') args.draco3d = path.resolve(value());
    else if (arg === '--rounds') args.rounds = Number(value());
    else if (arg === '--warmup') args.warmup = Number(value());
    else if (arg === '--tsv') args.tsv = value();
    else if (arg === '--clock') args.clock = value();
    else if (arg.startsWith('--')) throw new Error(`unknown option ${arg}`);
    else args.index = arg;
  }
  if (!['cpu', 'wall'].includes(args.clock)) {
    throw new Error('--clock is cpu or wall');
  }
  if (!args.index) {
    throw new Error('usage: web_decode_bench.js [options] INDEX.tsv');
  }
  if (!(args.rounds >= 1) || !(args.warmup >= 0)) {
    throw new Error('--rounds must be >= 1 and --warmup >= 0');
  }
  return args;
}

// Rows of INDEX.tsv grouped by mesh, in file order: {mesh, kind, uvVertices,
// files: [{scheme, data, bytes}]}, the stock file first.
function readIndex(indexPath) {
  const lines = fs.readFileSync(indexPath, 'utf8').split('\n').filter(Boolean);
  const header = lines.shift().split('\t');
  const column = (name) => {
    const at = header.indexOf(name);
    if (at < 0) throw new Error(`${indexPath}: no column ${name}`);
    return at;
  };
  const [cMesh, cKind, cUv, cScheme, cFile] =
      ['mesh', 'kind', 'uv_vertices', 'scheme', 'file'].map(column);
  const meshes = new Map();
  for (const line of lines) {
    const row = line.split('\t');
    if (!meshes.has(row[cMesh])) {
      meshes.set(row[cMesh], {mesh: row[cMesh], kind: row[cKind],
                              uvVertices: row[cUv], files: []});
    }
    const file = path.resolve(path.dirname(indexPath), row[cFile]);
    const data = new Int8Array(fs.readFileSync(file));
    meshes.get(row[cMesh]).files.push({scheme: row[cScheme], data,
                                       bytes: data.byteLength});
  }
  for (const entry of meshes.values()) {
    entry.files.sort((a, b) => (b.scheme === 'stock') - (a.scheme === 'stock'));
    if (entry.files[0].scheme !== 'stock') {
      throw new Error(`${entry.mesh}: no stock-coded file in the index`);
    }
  }
  return [...meshes.values()];
}

// Starts a stopwatch; calling what it returns gives {wall, cpu} in ms since.
function stopwatch() {
  const cpuStart = process.cpuUsage();
  const start = performance.now();
  return () => {
    const wall = performance.now() - start;
    const cpu = process.cpuUsage(cpuStart);
    return {wall, cpu: (cpu.user + cpu.system) / 1000};
  };
}

// One decode as three.js's DRACOLoader does it. Returns the faces and
// {type: Float32Array} of the attributes present and, in |call|, the times of
// the DecodeArrayToMesh call alone; throws on failure.
function decodeLikeThree(draco, data) {
  const decoder = new draco.Decoder();
  const mesh = new draco.Mesh();
  try {
    if (decoder.GetEncodedGeometryType(data) !== draco.TRIANGULAR_MESH) {
      throw new Error('not a triangular mesh');
    }
    const elapsed = stopwatch();
    const status = decoder.DecodeArrayToMesh(data, data.byteLength, mesh);
    const call = elapsed();
    if (!status.ok() || mesh.ptr === 0) {
      throw new Error(`decoding failed: ${status.error_msg()}`);
    }
    const numPoints = mesh.num_points();
    const attributes = {};
    for (const type of kAttributeTypes) {
      const id = decoder.GetAttributeId(mesh, draco[type]);
      if (id === -1) continue;
      const attribute = decoder.GetAttribute(mesh, id);
      const numValues = numPoints * attribute.num_components();
      const byteLength = numValues * 4;
      const ptr = draco._malloc(byteLength);
      decoder.GetAttributeDataArrayForAllPoints(mesh, attribute,
                                                draco.DT_FLOAT32, byteLength,
                                                ptr);
      attributes[type] = {
        components: attribute.num_components(),
        values: new Float32Array(draco.HEAPF32.buffer, ptr, numValues).slice(),
      };
      draco._free(ptr);
    }
    const numIndices = mesh.num_faces() * 3;
    const ptr = draco._malloc(numIndices * 4);
    decoder.GetTrianglesUInt32Array(mesh, numIndices * 4, ptr);
    const index =
        new Uint32Array(draco.HEAPF32.buffer, ptr, numIndices).slice();
    draco._free(ptr);
    return {index, attributes, call};
  } finally {
    draco.destroy(mesh);
    draco.destroy(decoder);
  }
}

// Every attribute's values at every face corner, in face order.
function cornerValues(decoded) {
  const out = {};
  for (const [type, {components, values}] of
       Object.entries(decoded.attributes)) {
    const corners = new Float32Array(decoded.index.length * components);
    decoded.index.forEach((point, corner) => {
      for (let c = 0; c < components; ++c) {
        corners[corner * components + c] = values[point * components + c];
      }
    });
    out[type] = corners;
  }
  return out;
}

function sameBytes(a, b) {
  return a.length === b.length &&
      Buffer.from(a.buffer, a.byteOffset, a.byteLength)
          .equals(Buffer.from(b.buffer, b.byteOffset, b.byteLength));
}

// Checks the decoders' outputs for one mesh (see the header); returns a note
// for the Laplacian files ("max |dUV| ..."), throws on a mismatch.
function checkOutputs(entry, stock, ours) {
  const reference = decodeLikeThree(stock, entry.files[0].data);
  const ourStock = decodeLikeThree(ours, entry.files[0].data);
  if (!sameBytes(reference.index, ourStock.index) ||
      Object.keys(reference.attributes).some((type) =>
        !sameBytes(reference.attributes[type].values,
                   ourStock.attributes[type].values))) {
    throw new Error(`${entry.mesh}: our decoder and draco3d disagree on the ` +
                    'stock-coded file');
  }
  const expected = cornerValues(reference);
  const notes = [];
  for (const file of entry.files.slice(1)) {
    const got = cornerValues(decodeLikeThree(ours, file.data));
    for (const type of Object.keys(expected)) {
      if (!got[type]) {
        throw new Error(`${entry.mesh} ${file.scheme}: no ${type}`);
      }
      if (sameBytes(expected[type], got[type])) continue;
      if (type !== 'TEX_COORD' || !(file.scheme.startsWith('laplacian') ||
                                    file.scheme.startsWith('rmse'))) {
        throw new Error(`${entry.mesh} ${file.scheme}: ${type} differs from ` +
                        'the stock-coded file');
      }
      let maxDiff = 0;
      for (let i = 0; i < got[type].length; ++i) {
        maxDiff = Math.max(maxDiff, Math.abs(got[type][i] - expected[type][i]));
      }
      notes.push(`${file.scheme} max |dUV| ${maxDiff.toExponential(1)}`);
    }
  }
  return notes;
}

// The decodes of one mesh, in the order of a round: draco3d on the stock
// file, ours on the stock file, ours on each draco-uv file.
function decodeJobs(entry, stock, ours) {
  return [
    {key: 'draco3d', draco: stock, file: entry.files[0]},
    ...entry.files.map((file) => ({key: file.scheme === 'stock' ? 'ours' :
                                                                  file.scheme,
                                   draco: ours, file})),
  ];
}

// Times every decode of one mesh on four clocks (kClockNames): the whole
// decode and the DecodeArrayToMesh call alone, each in wall time
// (performance.now) and in the process's CPU time (process.cpuUsage, user +
// system), which a busy machine's preemptions do not inflate. Returns
// {key: {bytes, CLOCK: {min, median}}}.
function timeMesh(entry, stock, ours, args) {
  const jobs = decodeJobs(entry, stock, ours);
  const clocks = Object.keys(kClockNames);
  const times = jobs.map(() => Object.fromEntries(clocks.map((c) => [c, []])));
  const gc = typeof global.gc === 'function' ? global.gc : () => {};
  for (let round = 0; round < args.warmup + args.rounds; ++round) {
    for (let k = 0; k < jobs.length; ++k) {
      const j = (k + round) % jobs.length;
      gc();
      const elapsed = stopwatch();
      const {call} = decodeLikeThree(jobs[j].draco, jobs[j].file.data);
      const whole = elapsed();
      if (round < args.warmup) continue;
      times[j].wall.push(whole.wall);
      times[j].cpu.push(whole.cpu);
      times[j].callWall.push(call.wall);
      times[j].callCpu.push(call.cpu);
    }
  }
  const result = {};
  jobs.forEach((job, j) => {
    result[job.key] = {bytes: job.file.bytes};
    for (const clock of clocks) {
      const sorted = times[j][clock].sort((a, b) => a - b);
      result[job.key][clock] = {min: sorted[0], median: median(sorted)};
    }
  });
  return result;
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

const fmtMs = (ms) => ms.toFixed(ms < 1 ? 3 : 2);
const fmtRatio = (r) => r.toFixed(3);

// Minimum time of decode |key| of result |r| on |clock|, and its ratio to
// decode |base|.
const minTime = (r, key, clock) => r.times[key][clock].min;
const ratio = (r, key, base, clock) =>
  minTime(r, key, clock) / minTime(r, base, clock);

function perMeshTables(results, schemes, clock) {
  const out = [`### Times (ms, minimum ${kClockNames[clock]})`, ''];
  out.push('| mesh | kind | UV vertices | draco3d | ours | ' +
           `${schemes.join(' | ')} |`);
  out.push('| --- | --- | ---: | ---: | ---: |' +
           ' ---: |'.repeat(schemes.length));
  for (const r of results) {
    out.push(`| ${r.mesh} | ${r.kind} | ${r.uvVertices} | ` +
             ['draco3d', 'ours', ...schemes]
                 .map((k) => fmtMs(minTime(r, k, clock))).join(' | ') + ' |');
  }
  out.push('');
  const callClock = clock === 'wall' ? 'callWall' : 'callCpu';
  for (const [base, ratioClock, title] of [
    ['draco3d', clock, 'against draco3d on the stock-coded file (the ' +
                       'target\'s ratio)'],
    ['ours', clock, 'against our decoder on the stock-coded file'],
    ['ours', callClock, 'against our decoder on the stock-coded file (the ' +
                        'native instruction ratios\' analogue)']]) {
    const keys = base === 'draco3d' ? ['ours', ...schemes] : schemes;
    out.push(`### Ratios ${title}, ${kClockNames[ratioClock]}`, '');
    out.push(`| mesh | kind | ${keys.join(' | ')} |`);
    out.push(`| --- | --- |${' ---: |'.repeat(keys.length)}`);
    for (const r of results) {
      out.push(`| ${r.mesh} | ${r.kind} | ` + keys.map((k) =>
        fmtRatio(ratio(r, k, base, ratioClock))).join(' | ') + ' |');
    }
    out.push('');
  }
  return out;
}

function summaryTable(results, schemes) {
  const out = ['### Summary per scheme (medians over the meshes; ' +
               'wall / CPU time)', ''];
  out.push('| decode | vs draco3d | vs ours on the stock file | ' +
           'same, DecodeArrayToMesh only | ' +
           `within ${kTarget}× of draco3d | worst mesh vs draco3d | ` +
           'bytes vs stock |');
  out.push('| --- | ---: | ---: | ---: | ---: | --- | ---: |');
  const both = (f, clocks = ['wall', 'cpu']) => clocks.map(f).join(' / ');
  for (const key of ['ours', ...schemes]) {
    const vs = (base, clock) => results.map((r) => ratio(r, key, base, clock));
    const worst = (clock) => {
      const values = vs('draco3d', clock);
      const at = values.indexOf(Math.max(...values));
      return `${results[at].mesh} ${fmtRatio(values[at])}`;
    };
    const bytes = results.map((r) => r.times[key].bytes / r.times.ours.bytes);
    out.push(`| ${key === 'ours' ? 'ours, stock file' : key} | ` +
             both((c) => fmtRatio(median(vs('draco3d', c)))) + ' | ' +
             (key === 'ours' ? '1 | 1' :
               both((c) => fmtRatio(median(vs('ours', c)))) + ' | ' +
               both((c) => fmtRatio(median(vs('ours', c))),
                    ['callWall', 'callCpu'])) + ' | ' +
             both((c) => vs('draco3d', c).filter((v) => v <= kTarget).length) +
             ` of ${results.length} | ${both(worst)} | ` +
             `${fmtRatio(median(bytes))} |`);
  }
  out.push('');
  return out;
}

function perKindTable(results, schemes, clock) {
  const kinds = [...new Set(results.map((r) => r.kind))].sort();
  const out = [`### Medians per kind, ${kClockNames[clock]} (vs draco3d on ` +
               'the stock file; vs ours on the stock file in parentheses)', ''];
  out.push(`| kind | meshes | ours | ${schemes.join(' | ')} |`);
  out.push(`| --- | ---: | ---: |${' ---: |'.repeat(schemes.length)}`);
  for (const kind of kinds) {
    const rs = results.filter((r) => r.kind === kind);
    const of = (k, base) =>
      fmtRatio(median(rs.map((r) => ratio(r, k, base, clock))));
    out.push(`| ${kind} | ${rs.length} | ${of('ours', 'draco3d')} | ` +
             schemes.map((k) => `${of(k, 'draco3d')} (${of(k, 'ours')})`)
                 .join(' | ') + ' |');
  }
  out.push('');
  return out;
}

function printReport(results, schemes, args) {
  const out = [];
  out.push(`${results.length} meshes, minimum of ${args.rounds} interleaved ` +
           `rounds after ${args.warmup} warm-up rounds. "draco3d" = npm ` +
           'draco3d on the stock-coded file, "ours" = our decoder on the ' +
           'stock-coded file; a scheme column is our decoder on that ' +
           'scheme\'s file.', '');
  out.push(...summaryTable(results, schemes));
  out.push(...perKindTable(results, schemes, args.clock));
  out.push(...perMeshTables(results, schemes, args.clock));

  for (const clock of Object.keys(kClockNames)) {
    const spreads = results.flatMap((r) =>
      Object.values(r.times).map((t) => t[clock].median / t[clock].min));
    out.push(`Noise, ${kClockNames[clock]}: a file's median round over its ` +
             `minimum is ${fmtRatio(median(spreads))} at the median, ` +
             `${fmtRatio(Math.max(...spreads))} at most.`);
  }
  if (schemes.includes('auto')) {
    const auto = (clock) =>
      median(results.map((r) => ratio(r, 'auto', 'draco3d', clock)));
    const verdict = ['wall', 'cpu'].every((c) => auto(c) <= kTarget) ?
        'met' : 'not met';
    out.push(`Target \`auto\` ≤ ${kTarget}× draco3d on the corpus median: ` +
             `${fmtRatio(auto('wall'))} (wall) / ${fmtRatio(auto('cpu'))} ` +
             `(CPU) → **${verdict}**.`);
  }
  const notes = results.filter((r) => r.notes.length)
      .map((r) => `${r.mesh} ${r.notes.join(', ')}`);
  if (notes.length) {
    out.push('', 'Every lossless file decodes to the stock-coded file\'s ' +
             'values at every face corner; the Laplacian files\' largest UV ' +
             'differences: ' + notes.join('; ') + '.');
  }
  console.log(out.join('\n'));
}

function writeTsv(file, results) {
  const clocks = Object.keys(kClockNames);
  const rows = [['mesh', 'kind', 'uv_vertices', 'decode', 'bytes',
                 ...clocks.flatMap((c) => [`${c}_min_ms`, `${c}_median_ms`])]
      .join('\t')];
  for (const r of results) {
    for (const [key, t] of Object.entries(r.times)) {
      rows.push([r.mesh, r.kind, r.uvVertices, key, t.bytes,
                 ...clocks.flatMap((c) => [t[c].min.toFixed(4),
                                           t[c].median.toFixed(4)])]
          .join('\t'));
    }
  }
  fs.writeFileSync(file, rows.join('\n') + '\n');
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const entries = readIndex(args.index);
  if (entries.length === 0) throw new Error(`${args.index}: no files`);
  const stock = await require(path.join(args.draco3d, 'draco3d.js'))
      .createDecoderModule({});
  const ours = await require(path.join(args.ours, 'draco3d.js'))
      .createDecoderModule({});
  const schemes = entries[0].files.slice(1).map((f) => f.scheme);
  const results = [];
  for (const entry of entries) {
    const have = entry.files.slice(1).map((f) => f.scheme).join();
    if (have !== schemes.join()) {
      throw new Error(`${entry.mesh}: schemes ${have}, expected ${schemes}`);
    }
    const notes = checkOutputs(entry, stock, ours);
    const times = timeMesh(entry, stock, ours, args);
    process.stderr.write(`${entry.mesh}: draco3d ` +
                         `${fmtMs(times.draco3d.wall.min)} ours ` +
                         `${fmtMs(times.ours.wall.min)} ms\n`);
    results.push({mesh: entry.mesh, kind: entry.kind,
                  uvVertices: entry.uvVertices, times, notes});
  }
  if (args.tsv) writeTsv(args.tsv, results);
  printReport(results, schemes, args);
}

main().catch((error) => {
  console.error(error.message || error);
  process.exit(1);
});
