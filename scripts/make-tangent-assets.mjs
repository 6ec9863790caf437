#!/usr/bin/env node
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
 * Makes GLB test and benchmark assets with glTF TANGENT attributes, the way
 * asset pipelines make them: MikkTSpace tangents from glTF-Transform's
 * tangents() with the npm `mikktspace` package.
 *
 * It runs on the npm packages pinned in tests/web (@gltf-transform/core and
 * /functions 4.5.1, mikktspace 1.1.1), installed once with
 *
 *   (cd tests/web && npm ci --ignore-scripts)
 *
 * (or by ./draco-uv.sh test); it loads them from tests/web/node_modules
 * wherever it is run from.
 *
 *   node scripts/make-tangent-assets.mjs [--corpus DIR] [--out DIR]
 *        [--draco-testdata DIR] [--no-obj] [--no-own] [NAME...]
 *   node scripts/make-tangent-assets.mjs --obj [--out DIR] [--suffix S] FILE.obj...
 *
 * Corpus mode (the first form) writes OUT/NAME.glb and OUT/MANIFEST.tsv
 * (name, file, kind, source, tangents, vertices, triangles) for
 *  - every row of CORPUS/MANIFEST.tsv (columns name, file, kind) but those of
 *    kind synthetic-test: the OBJ (v, vt and f v/vt; no normals needed)
 *    converted as below, tangents=mikktspace;
 *  - unless --no-own, the glTF assets with their own tangents listed in
 *    scripts/tangent-assets-gltf.tsv (Khronos samples in CORPUS/gltf and in
 *    Draco's testdata), copied as geometry-only GLBs (materials, textures and
 *    material extensions dropped; vertices, tangents, nodes and meshes as
 *    they are), named NAME_own, tangents=own. They are read where they are
 *    and written only to OUT, never into the repository.
 * NAMEs (corpus or _own names) restrict it to those assets.
 *
 * --obj mode converts the given OBJ files to OUT/BASENAME<S>.glb (default
 * suffix "", out "."), without a manifest; testdata/README.md has the command
 * that made testdata/*_tangents.glb.
 *
 * The conversion of an OBJ:
 *  1. triangles of the OBJ's faces (polygons fan-triangulated; repeated-index
 *     triangles kept), with their v and vt indices;
 *  2. one smooth normal per OBJ position (v), so that UV seams do not split
 *     normals: the area-weighted sum of the incident triangles' normals,
 *     normalised; where that sum vanishes (no incident area, or opposite
 *     faces cancelling) the normal of the largest incident triangle, or +Z
 *     when all incident triangles have zero area;
 *  3. a glTF-Transform Document with one mesh of one primitive: one glTF
 *     vertex per distinct (v, vt) pair in order of first use, float32
 *     POSITION, NORMAL and TEXCOORD_0 (the OBJ's values, v not flipped), and
 *     the triangles as indices;
 *  4. unweld(), tangents({generateTangents: mikktspace.generateTangents,
 *     overwrite: true}), weld(): MikkTSpace runs on unindexed triangles
 *     (tangents() flips its w for glTF's v axis), weld() merges the vertices
 *     that came out bitwise identical, tangents included, so a (v, vt) pair
 *     is split where MikkTSpace gave its corners different tangents. In
 *     glTF-Transform 4.5.1 tangents() needs no material with a normal
 *     texture (only TRIANGLES with POSITION, NORMAL and TEXCOORD_0 and no
 *     indices), so the Document gets no material and there is nothing to
 *     drop afterwards; the script fails if a primitive is left without
 *     TANGENT. Before weld(), repairZeroTangents() replaces the tangents
 *     MikkTSpace leaves at zero, which glTF forbids (ACCESSOR_VECTOR3_NON_UNIT):
 *     this happens at a vertex whose only triangle stands almost edge-on to
 *     its smooth normal, so that the triangle's corner angle projected into
 *     the normal's plane (MikkTSpace's weight) is about 0.01 degrees
 *     (one vertex each in khr_dragon and stk_abyss_track);
 *  5. the GLB as glTF-Transform's NodeIO writes it. The output is a function
 *     of the input bytes alone: a re-run writes the same bytes.
 *
 * Progress goes to stdout, one line per asset (name, vertices, triangles,
 * seconds). Draco's buffers do not depend on materials, so none are written.
 *
 * Defaults: CORPUS = $DRACO_UV_CORPUS or ../shared/corpus next to the
 * repository; OUT = build/tangent-assets; Draco testdata = $DRACO_TESTDATA
 * or third_party/debian-draco-1.5.5+dfsg-2/testdata (scripts/
 * fetch-draco-source.sh). Relative paths are relative to the current folder.
 */

import fs from 'node:fs';
import {createRequire} from 'node:module';
import path from 'node:path';
import {fileURLToPath, pathToFileURL} from 'node:url';

export const kRepo =
    path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const kOwnList = path.join(kRepo, 'scripts', 'tangent-assets-gltf.tsv');

/** The pinned npm packages of tests/web, loaded from its node_modules. */
export function loadPackages() {
  const require = createRequire(path.join(kRepo, 'tests/web/package.json'));
  try {
    return {
      core: require('@gltf-transform/core'),
      extensions: require('@gltf-transform/extensions'),
      functions: require('@gltf-transform/functions'),
      mikktspace: require('mikktspace'),
    };
  } catch (e) {
    throw new Error(
        `cannot load tests/web's npm packages (${e.message.split('\n')[0]}); ` +
        'install them with: (cd tests/web && npm ci --ignore-scripts)');
  }
}

/**
 * Parses an OBJ's v, vt and f records. Returns the float32 positions and
 * UVs as given and, per triangle corner, its v and vt index (0-based).
 */
export function parseObj(text, label = 'OBJ') {
  const positions = [];
  const uvs = [];
  const cornerV = [];
  const cornerVt = [];
  const lines = text.split('\n');
  for (let ln = 0; ln < lines.length; ln++) {
    const line = lines[ln].trimStart();
    const c0 = line.charCodeAt(0);
    if (c0 !== 118 /* v */ && c0 !== 102 /* f */) continue;
    const t = line.trim().split(/\s+/);
    const where = () => `${label}:${ln + 1}`;
    if (t[0] === 'v') {
      if (t.length < 4) throw new Error(`${where()}: v needs x y z`);
      for (let k = 1; k <= 3; k++) positions.push(Math.fround(Number(t[k])));
    } else if (t[0] === 'vt') {
      if (t.length < 3) throw new Error(`${where()}: vt needs u v`);
      uvs.push(Math.fround(Number(t[1])), Math.fround(Number(t[2])));
    } else if (t[0] === 'f') {
      const nv = positions.length / 3;
      const nt = uvs.length / 2;
      const v = [];
      const vt = [];
      for (let k = 1; k < t.length; k++) {
        const parts = t[k].split('/');
        if (parts.length < 2 || parts[1] === '') {
          throw new Error(`${where()}: face corner '${t[k]}' has no vt index`);
        }
        let a = parseInt(parts[0], 10);
        let b = parseInt(parts[1], 10);
        a = a < 0 ? nv + a : a - 1;
        b = b < 0 ? nt + b : b - 1;
        if (!(a >= 0 && a < nv) || !(b >= 0 && b < nt)) {
          throw new Error(`${where()}: face index out of range`);
        }
        v.push(a);
        vt.push(b);
      }
      if (v.length < 3) throw new Error(`${where()}: face with < 3 corners`);
      for (let k = 1; k + 1 < v.length; k++) {
        cornerV.push(v[0], v[k], v[k + 1]);
        cornerVt.push(vt[0], vt[k], vt[k + 1]);
      }
    }
  }
  const position = Float32Array.from(positions);
  for (const x of position) {
    if (!Number.isFinite(x)) throw new Error(`${label}: non-finite position`);
  }
  const uv = Float32Array.from(uvs);
  for (const x of uv) {
    if (!Number.isFinite(x)) throw new Error(`${label}: non-finite vt`);
  }
  if (cornerV.length === 0) throw new Error(`${label}: no faces`);
  return {
    position,
    uv,
    cornerV: Uint32Array.from(cornerV),
    cornerVt: Uint32Array.from(cornerVt),
  };
}

/**
 * One unit normal per position: the area-weighted sum of the incident
 * triangles' normals (their cross products), in double precision from the
 * float32 positions. Where the sum vanishes (|sum| <= 1e-6 * sum of |cross|)
 * the normal of the largest incident triangle, and +Z where every incident
 * triangle has zero area (also, unused, for positions no triangle uses).
 * Returns {normal: Float32Array, fallbacks: how many used positions fell back}.
 */
export function smoothNormals(position, cornerV) {
  const n = position.length / 3;
  const sum = new Float64Array(3 * n);
  const mag = new Float64Array(n);     // sum of |cross| per position
  const best = new Float64Array(3 * n);  // largest incident cross product
  const bestMag = new Float64Array(n);
  const used = new Uint8Array(n);
  for (let c = 0; c < cornerV.length; c += 3) {
    const a = 3 * cornerV[c], b = 3 * cornerV[c + 1], d = 3 * cornerV[c + 2];
    const ux = position[b] - position[a], uy = position[b + 1] - position[a + 1],
          uz = position[b + 2] - position[a + 2];
    const vx = position[d] - position[a], vy = position[d + 1] - position[a + 1],
          vz = position[d + 2] - position[a + 2];
    const x = uy * vz - uz * vy, y = uz * vx - ux * vz, z = ux * vy - uy * vx;
    const m = Math.hypot(x, y, z);
    for (let k = 0; k < 3; k++) {
      const p = cornerV[c + k];
      used[p] = 1;
      sum[3 * p] += x;
      sum[3 * p + 1] += y;
      sum[3 * p + 2] += z;
      mag[p] += m;
      if (m > bestMag[p]) {
        bestMag[p] = m;
        best[3 * p] = x;
        best[3 * p + 1] = y;
        best[3 * p + 2] = z;
      }
    }
  }
  const normal = new Float32Array(3 * n);
  let fallbacks = 0;
  for (let p = 0; p < n; p++) {
    let x = sum[3 * p], y = sum[3 * p + 1], z = sum[3 * p + 2];
    let len = Math.hypot(x, y, z);
    if (!(len > 1e-6 * mag[p])) {
      if (used[p]) fallbacks++;
      if (bestMag[p] > 0) {
        x = best[3 * p];
        y = best[3 * p + 1];
        z = best[3 * p + 2];
        len = bestMag[p];
      } else {
        x = 0;
        y = 0;
        z = 1;
        len = 1;
      }
    }
    normal[3 * p] = x / len;
    normal[3 * p + 1] = y / len;
    normal[3 * p + 2] = z / len;
  }
  return {normal, fallbacks};
}

/**
 * The glTF-Transform Document of an OBJ (steps 1-3 above): one primitive
 * with POSITION, NORMAL, TEXCOORD_0 and indices, no material.
 */
export function objToDocument(pkgs, text, name, label = name) {
  const {Document, Logger} = pkgs.core;
  const obj = parseObj(text, label);
  const {normal: posNormal, fallbacks} = smoothNormals(obj.position, obj.cornerV);
  const numVt = obj.uv.length / 2;
  const vertexOf = new Map();
  const srcV = [];
  const srcVt = [];
  const indices = new Uint32Array(obj.cornerV.length);
  for (let c = 0; c < obj.cornerV.length; c++) {
    const key = obj.cornerV[c] * numVt + obj.cornerVt[c];
    let i = vertexOf.get(key);
    if (i === undefined) {
      i = srcV.length;
      vertexOf.set(key, i);
      srcV.push(obj.cornerV[c]);
      srcVt.push(obj.cornerVt[c]);
    }
    indices[c] = i;
  }
  const nv = srcV.length;
  const position = new Float32Array(3 * nv);
  const normal = new Float32Array(3 * nv);
  const texcoord = new Float32Array(2 * nv);
  for (let i = 0; i < nv; i++) {
    for (let k = 0; k < 3; k++) {
      position[3 * i + k] = obj.position[3 * srcV[i] + k];
      normal[3 * i + k] = posNormal[3 * srcV[i] + k];
    }
    texcoord[2 * i] = obj.uv[2 * srcVt[i]];
    texcoord[2 * i + 1] = obj.uv[2 * srcVt[i] + 1];
  }
  const doc = new Document();
  doc.setLogger(new Logger(Logger.Verbosity.WARN));
  const buffer = doc.createBuffer();
  const accessor = (type, array) =>
      doc.createAccessor().setType(type).setArray(array).setBuffer(buffer);
  const prim = doc.createPrimitive()
                   .setAttribute('POSITION', accessor('VEC3', position))
                   .setAttribute('NORMAL', accessor('VEC3', normal))
                   .setAttribute('TEXCOORD_0', accessor('VEC2', texcoord))
                   .setIndices(accessor('SCALAR', indices));
  const mesh = doc.createMesh(name).addPrimitive(prim);
  const scene = doc.createScene(name).addChild(doc.createNode(name).setMesh(mesh));
  doc.getRoot().setDefaultScene(scene);
  return {
    doc,
    stats: {
      positions: obj.position.length / 3,
      uvs: numVt,
      triangles: indices.length / 3,
      vertices: nv,
      normalFallbacks: fallbacks,
    },
  };
}

/**
 * MikkTSpace can leave a tangent's xyz at zero (see step 4 above); glTF
 * requires unit tangents. Each such tangent (|xyz| < 0.5) becomes the unit
 * vector orthogonal to the vertex normal made from the coordinate axis least
 * aligned with it (x before y before z on ties); w stays. Depends on the
 * vertex's own NORMAL and TANGENT alone, so it commutes with weld(). Returns
 * how many tangents it replaced.
 */
export function repairZeroTangents(doc) {
  let repaired = 0;
  for (const mesh of doc.getRoot().listMeshes()) {
    for (const prim of mesh.listPrimitives()) {
      const tangent = prim.getAttribute('TANGENT');
      const normal = prim.getAttribute('NORMAL');
      if (!tangent || !normal) continue;
      const t = tangent.getArray();
      const n = normal.getArray();
      for (let i = 0; i < t.length / 4; i++) {
        if (Math.hypot(t[4 * i], t[4 * i + 1], t[4 * i + 2]) >= 0.5) continue;
        const nx = n[3 * i], ny = n[3 * i + 1], nz = n[3 * i + 2];
        const ax = Math.abs(nx), ay = Math.abs(ny), az = Math.abs(nz);
        const e = ax <= ay && ax <= az ? [1, 0, 0] : ay <= az ? [0, 1, 0] : [0, 0, 1];
        const d = e[0] * nx + e[1] * ny + e[2] * nz;
        const x = e[0] - d * nx, y = e[1] - d * ny, z = e[2] - d * nz;
        const len = Math.hypot(x, y, z);
        t[4 * i] = x / len;
        t[4 * i + 1] = y / len;
        t[4 * i + 2] = z / len;
        repaired++;
      }
      tangent.setArray(t);
    }
  }
  return repaired;
}

/**
 * Step 4: unweld(), tangents() with mikktspace, repairZeroTangents(),
 * weld(). Throws if some triangle primitive is left without TANGENT.
 * Returns how many (unwelded) tangents were repaired.
 */
export async function addMikkTangents(pkgs, doc) {
  const {unweld, tangents, weld} = pkgs.functions;
  await doc.transform(
      unweld(),
      tangents({generateTangents: pkgs.mikktspace.generateTangents, overwrite: true}));
  const repaired = repairZeroTangents(doc);
  await doc.transform(weld());
  for (const mesh of doc.getRoot().listMeshes()) {
    for (const prim of mesh.listPrimitives()) {
      if (!prim.getAttribute('TANGENT')) {
        throw new Error(`tangents() left a primitive of mesh '${mesh.getName()}' without TANGENT`);
      }
    }
  }
  return repaired;
}

/**
 * The primitives of a Document, those with the same indices and attribute
 * accessors as an earlier one left out (draco_transcoder encodes them once:
 * SpecGlossVsMetalRough's two meshes share one WaterBottle).
 */
export function distinctPrimitives(doc) {
  const ids = new Map();
  const id = (a) => {
    if (!a) return -1;
    if (!ids.has(a)) ids.set(a, ids.size);
    return ids.get(a);
  };
  const seen = new Set();
  const out = [];
  for (const mesh of doc.getRoot().listMeshes()) {
    for (const prim of mesh.listPrimitives()) {
      const key = [prim.getMode(), id(prim.getIndices()),
                   ...prim.listSemantics().map((s) => `${s}=${id(prim.getAttribute(s))}`)]
                      .join(',');
      if (seen.has(key)) continue;
      seen.add(key);
      out.push(prim);
    }
  }
  return out;
}

/** Vertices and triangles summed over the distinct triangle primitives. */
export function countDocument(pkgs, doc) {
  const {Primitive} = pkgs.core;
  let vertices = 0, triangles = 0, tangentVertices = 0;
  for (const prim of distinctPrimitives(doc)) {
    if (prim.getMode() !== Primitive.Mode.TRIANGLES) continue;
    const n = prim.getAttribute('POSITION').getCount();
    vertices += n;
    if (prim.getAttribute('TANGENT')) tangentVertices += n;
    const idx = prim.getIndices();
    triangles += (idx ? idx.getCount() : n) / 3;
  }
  return {vertices, triangles, tangentVertices};
}

/** The GLB of an OBJ with MikkTSpace tangents (steps 1-5). */
export async function objToTangentGlb(pkgs, text, name, label = name) {
  const {doc, stats} = objToDocument(pkgs, text, name, label);
  const repairedTangents = await addMikkTangents(pkgs, doc);
  const counts = countDocument(pkgs, doc);
  const glb = await new pkgs.core.NodeIO().writeBinary(doc);
  return {
    glb,
    stats: {...stats, vertices: counts.vertices, beforeTangents: stats.vertices, repairedTangents},
  };
}

/**
 * A glTF/GLB with its own tangents as a geometry-only GLB: materials,
 * textures and every extension but KHR_mesh_quantization dropped, buffers
 * merged into one (unpartition()); meshes, nodes and vertex data unchanged.
 * No prune(): with the materials gone it would drop TEXCOORD_0 and TANGENT
 * as unused.
 */
export async function geometryOnlyGlb(pkgs, file) {
  const {NodeIO, Logger} = pkgs.core;
  const io = new NodeIO().registerExtensions(pkgs.extensions.ALL_EXTENSIONS);
  const doc = await io.read(file);
  doc.setLogger(new Logger(Logger.Verbosity.WARN));
  if (doc.getRoot().listExtensionsUsed().some(
          (e) => e.extensionName === 'KHR_draco_mesh_compression' ||
              e.extensionName === 'EXT_meshopt_compression')) {
    throw new Error(`${file}: compressed input is not supported`);
  }
  for (const m of doc.getRoot().listMaterials()) m.dispose();
  for (const t of doc.getRoot().listTextures()) t.dispose();
  for (const e of doc.getRoot().listExtensionsUsed()) {
    if (e.extensionName !== 'KHR_mesh_quantization') e.dispose();
  }
  await doc.transform(pkgs.functions.unpartition());  // a GLB has one buffer
  if (!countDocument(pkgs, doc).tangentVertices) {
    throw new Error(`${file}: no primitive with TANGENT`);
  }
  return {glb: await io.writeBinary(doc), stats: countDocument(pkgs, doc)};
}

/** Rows of a TSV with a header line (lines starting with # skipped). */
export function readTsv(file) {
  const lines = fs.readFileSync(file, 'utf8').split('\n')
                    .filter((l) => l.trim() !== '' && !l.startsWith('#'));
  const header = lines[0].split('\t');
  return lines.slice(1).map((l) => {
    const cells = l.split('\t');
    return Object.fromEntries(header.map((h, i) => [h, cells[i] ?? '']));
  });
}

function usage(message) {
  if (message) console.error(`make-tangent-assets: ${message}`);
  console.error(
      'usage: node scripts/make-tangent-assets.mjs [--corpus DIR] [--out DIR]\n' +
      '         [--draco-testdata DIR] [--no-obj] [--no-own] [NAME...]\n' +
      '       node scripts/make-tangent-assets.mjs --obj [--out DIR] [--suffix S] FILE.obj...');
  process.exit(2);
}

function parseArgs(argv) {
  const o = {
    corpus: process.env.DRACO_UV_CORPUS || path.join(kRepo, '..', 'shared', 'corpus'),
    out: null,
    dracoTestdata: process.env.DRACO_TESTDATA ||
        path.join(kRepo, 'third_party', 'debian-draco-1.5.5+dfsg-2', 'testdata'),
    obj: false,
    suffix: '',
    doObj: true,
    doOwn: true,
    names: [],
  };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) usage(`${a} needs a value`);
      return argv[++i];
    };
    if (a === '--corpus') o.corpus = value();
    else if (a === '--out') o.out = value();
    else if (a === '--draco-testdata') o.dracoTestdata = value();
    else if (a === '--suffix') o.suffix = value();
    else if (a === '--obj') o.obj = true;
    else if (a === '--no-obj') o.doObj = false;
    else if (a === '--no-own') o.doOwn = false;
    else if (a === '-h' || a === '--help') usage();
    else if (a.startsWith('-')) usage(`unknown option ${a}`);
    else o.names.push(a);
  }
  o.out ??= o.obj ? '.' : path.join(kRepo, 'build', 'tangent-assets');
  return o;
}

function progress(name, s, seconds) {
  const split = s.beforeTangents !== undefined && s.beforeTangents !== s.vertices ?
      ` (${s.beforeTangents} before tangents)` : '';
  const fallback = (s.normalFallbacks ? `, ${s.normalFallbacks} fallback normals` : '') +
      (s.repairedTangents ? `, ${s.repairedTangents} zero tangents repaired (unwelded)` : '');
  console.log(`${name}: ${s.vertices} vertices${split}, ${s.triangles} triangles` +
              `${fallback}, ${seconds.toFixed(2)} s`);
}

async function main() {
  const o = parseArgs(process.argv.slice(2));
  const pkgs = loadPackages();
  fs.mkdirSync(o.out, {recursive: true});
  const t0 = performance.now();

  if (o.obj) {
    if (!o.names.length) usage('--obj needs OBJ files');
    for (const file of o.names) {
      const name = path.basename(file).replace(/\.obj$/i, '') + o.suffix;
      const t = performance.now();
      const {glb, stats} =
          await objToTangentGlb(pkgs, fs.readFileSync(file, 'utf8'), name, file);
      fs.writeFileSync(path.join(o.out, `${name}.glb`), glb);
      progress(name, stats, (performance.now() - t) / 1000);
    }
    return;
  }

  const jobs = [];
  if (o.doObj) {
    const manifest = path.join(o.corpus, 'MANIFEST.tsv');
    if (!fs.existsSync(manifest)) {
      usage(`no corpus manifest ${manifest} (--corpus DIR, or --no-obj)`);
    }
    for (const row of readTsv(manifest)) {
      if (row.kind === 'synthetic-test') continue;
      jobs.push({name: row.name, kind: row.kind, tangents: 'mikktspace',
                 source: path.join(o.corpus, row.file), obj: true});
    }
  }
  if (o.doOwn) {
    const roots = {'corpus': o.corpus, 'draco-testdata': o.dracoTestdata};
    for (const row of readTsv(kOwnList)) {
      const [root, rel] = row.path.split(/:(.*)/s);
      if (!(root in roots)) throw new Error(`${kOwnList}: unknown root in ${row.path}`);
      jobs.push({name: row.name, kind: row.kind, tangents: 'own',
                 source: path.join(roots[root], rel), obj: false});
    }
  }
  const selected = o.names.length ? jobs.filter((j) => o.names.includes(j.name)) : jobs;
  const unknown = o.names.filter((n) => !jobs.some((j) => j.name === n));
  if (unknown.length) usage(`unknown asset name(s): ${unknown.join(', ')}`);
  const missing = selected.filter((j) => !fs.existsSync(j.source));
  if (missing.length) {
    usage('missing input(s) (--corpus, --draco-testdata, --no-own):\n  ' +
          missing.map((j) => j.source).join('\n  '));
  }

  const rows = [['name', 'file', 'kind', 'source', 'tangents', 'vertices', 'triangles']];
  for (const job of selected) {
    const t = performance.now();
    const {glb, stats} = job.obj ?
        await objToTangentGlb(pkgs, fs.readFileSync(job.source, 'utf8'), job.name,
                              job.source) :
        await geometryOnlyGlb(pkgs, job.source);
    const file = `${job.name}.glb`;
    fs.writeFileSync(path.join(o.out, file), glb);
    progress(job.name, stats, (performance.now() - t) / 1000);
    rows.push([job.name, file, job.kind, job.source, job.tangents, stats.vertices,
               stats.triangles]);
  }
  fs.writeFileSync(path.join(o.out, 'MANIFEST.tsv'),
                   rows.map((r) => r.join('\t')).join('\n') + '\n');
  console.log(`${selected.length} assets in ${o.out} ` +
              `(${((performance.now() - t0) / 1000).toFixed(1)} s)`);
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  main().catch((e) => {
    console.error(`make-tangent-assets: ${e.stack || e}`);
    process.exit(1);
  });
}
