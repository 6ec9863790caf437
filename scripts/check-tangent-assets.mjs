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
 * Checks GLBs with TANGENT attributes, such as those of
 * scripts/make-tangent-assets.mjs:
 *  - Khronos glTF-Validator (npm gltf-validator, pinned in tests/web): no
 *    errors (warnings and infos are listed);
 *  - every TANGENT is float, xyz unit length within 1e-5 and w exactly +1
 *    or -1;
 *  - the tangents recomputed the way make-tangent-assets.mjs made them
 *    (unweld(), tangents() with mikktspace, repairZeroTangents(), weld())
 *    from the file's own
 *    positions, normals and UVs: per triangle corner, the angle to the
 *    stored tangent and whether w agrees; and whether the re-welded file
 *    writes back to the same bytes. For assets made with mikktspace
 *    (--mikktspace, or tangents=mikktspace in a MANIFEST.tsv) the check
 *    fails unless every corner matches within 1e-3 degrees with the same w
 *    (the same bytes are reported, not required); for others (tangents=own)
 *    the agreement is only printed.
 * Prints one line per file; exits 1 if a check fails.
 *
 *   node scripts/check-tangent-assets.mjs [--mikktspace] FILE.glb...
 *   node scripts/check-tangent-assets.mjs DIR     (DIR/MANIFEST.tsv of make-tangent-assets.mjs)
 *
 * Needs tests/web's npm packages: (cd tests/web && npm ci --ignore-scripts).
 */

import fs from 'node:fs';
import {createRequire} from 'node:module';
import path from 'node:path';
import {pathToFileURL} from 'node:url';

import {kRepo, loadPackages, readTsv, repairZeroTangents} from './make-tangent-assets.mjs';

const kUnitTolerance = 1e-5;
const kMikkMaxDegrees = 1e-3;

/** Khronos glTF-Validator's report of a GLB: counts and issue codes. */
export async function validate(bytes, uri) {
  const require = createRequire(path.join(kRepo, 'tests/web/package.json'));
  const validator = require('gltf-validator');
  const report = await validator.validateBytes(new Uint8Array(bytes), {
    uri,
    maxIssues: 0,
    externalResourceFunction: () => Promise.reject(new Error('no external resources')),
  });
  const codes = (severity) => {
    const count = new Map();
    for (const m of report.issues.messages) {
      if (m.severity === severity) count.set(m.code, (count.get(m.code) || 0) + 1);
    }
    return [...count].map(([c, n]) => `${c} x${n}`).join(', ');
  };
  return {
    errors: report.issues.numErrors,
    warnings: report.issues.numWarnings,
    infos: report.issues.numInfos,
    errorCodes: codes(0),
    warningCodes: codes(1),
    infoCodes: codes(2),
  };
}

/** Per-corner copy of a primitive's attribute (expanded through its indices). */
function perCorner(prim, semantic) {
  const acc = prim.getAttribute(semantic);
  const size = acc.getElementSize();
  const idx = prim.getIndices()?.getArray();
  const n = idx ? idx.length : acc.getCount();
  const out = new Float64Array(n * size);
  const el = [];
  for (let c = 0; c < n; c++) {
    acc.getElement(idx ? idx[c] : c, el);
    for (let k = 0; k < size; k++) out[c * size + k] = el[k];
  }
  return out;
}

/** Unit length and w of every TANGENT. */
function checkUnitAndSign(pkgs, doc) {
  const {Accessor} = pkgs.core;
  let maxLenError = 0, badW = 0, notFloat = 0, count = 0;
  for (const mesh of doc.getRoot().listMeshes()) {
    for (const prim of mesh.listPrimitives()) {
      const t = prim.getAttribute('TANGENT');
      if (!t) continue;
      if (t.getComponentType() !== Accessor.ComponentType.FLOAT || t.getNormalized()) notFloat++;
      const a = t.getArray();
      for (let i = 0; i < a.length; i += 4) {
        const len = Math.hypot(a[i], a[i + 1], a[i + 2]);
        const e = Math.abs(len - 1);
        if (!(e <= maxLenError)) maxLenError = Number.isFinite(e) ? Math.max(maxLenError, e) : Infinity;
        if (a[i + 3] !== 1 && a[i + 3] !== -1) badW++;
        count++;
      }
    }
  }
  return {count, maxLenError, badW, notFloat};
}

/**
 * Recomputes the tangents of a GLB with unweld(), tangents(mikktspace) and
 * compares them per corner with the stored ones; then weld() and write.
 */
async function recompute(pkgs, bytes) {
  const {NodeIO, Logger} = pkgs.core;
  const {unweld, tangents, weld} = pkgs.functions;
  const io = new NodeIO().registerExtensions(pkgs.extensions.ALL_EXTENSIONS);
  const doc = await io.readBinary(new Uint8Array(bytes));
  doc.setLogger(new Logger(Logger.Verbosity.WARN));
  const stored = [];
  for (const mesh of doc.getRoot().listMeshes()) {
    for (const prim of mesh.listPrimitives()) {
      stored.push(prim.getAttribute('TANGENT') ? perCorner(prim, 'TANGENT') : null);
    }
  }
  await doc.transform(
      unweld(),
      tangents({generateTangents: pkgs.mikktspace.generateTangents, overwrite: true}));
  const repaired = repairZeroTangents(doc);
  const angles = [];
  let wMismatch = 0, identical = 0, corners = 0;
  let p = 0;
  for (const mesh of doc.getRoot().listMeshes()) {
    for (const prim of mesh.listPrimitives()) {
      const s = stored[p++];
      if (!s) continue;
      const r = prim.getAttribute('TANGENT').getArray();
      for (let c = 0; c < s.length / 4; c++) {
        const a = s.subarray(4 * c, 4 * c + 4);
        const b = r.subarray(4 * c, 4 * c + 4);
        const dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const cross = Math.hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]);
        angles.push(Math.atan2(cross, dot) * 180 / Math.PI);
        if (Math.sign(a[3]) !== Math.sign(b[3])) wMismatch++;
        if (a[0] === b[0] && a[1] === b[1] && a[2] === b[2] && a[3] === b[3]) identical++;
        corners++;
      }
    }
  }
  await doc.transform(weld());
  const rewritten = await io.writeBinary(doc);
  angles.sort((x, y) => x - y);
  const q = (f) => angles[Math.min(angles.length - 1, Math.floor(f * angles.length))];
  return {
    corners,
    repaired,
    identical,
    wMismatch,
    median: q(0.5),
    p99: q(0.99),
    max: angles[angles.length - 1],
    sameBytes: Buffer.compare(Buffer.from(rewritten), Buffer.from(bytes)) === 0,
  };
}

/** All checks of one GLB; returns {line, ok}. */
export async function checkGlb(pkgs, file, mikktspace) {
  const bytes = fs.readFileSync(file);
  const v = await validate(bytes, path.basename(file));
  const doc = await new pkgs.core.NodeIO()
                  .registerExtensions(pkgs.extensions.ALL_EXTENSIONS)
                  .readBinary(new Uint8Array(bytes));
  const u = checkUnitAndSign(pkgs, doc);
  const r = await recompute(pkgs, bytes);
  const problems = [];
  if (v.errors) problems.push(`validator errors: ${v.errorCodes}`);
  if (!u.count) problems.push('no TANGENT');
  if (u.notFloat) problems.push(`${u.notFloat} TANGENT accessors not float`);
  if (!(u.maxLenError <= kUnitTolerance)) problems.push(`|xyz| off by ${u.maxLenError}`);
  if (u.badW) problems.push(`${u.badW} tangents with w not +-1`);
  if (mikktspace && (!(r.max <= kMikkMaxDegrees) || r.wMismatch)) {
    problems.push(`recomputed tangents differ (max ${r.max} deg, ${r.wMismatch} w)`);
  }
  const fmt = (x) => x.toPrecision(3);
  const line =
      `${path.basename(file)}: validator ${v.errors} errors, ${v.warnings} warnings` +
      `${v.warningCodes ? ` (${v.warningCodes})` : ''}, ${v.infos} infos` +
      `${v.infoCodes ? ` (${v.infoCodes})` : ''}; ${u.count} tangents, ` +
      `max ||xyz|-1| ${u.maxLenError.toExponential(1)}, ${u.badW} bad w; ` +
      `recomputed (${mikktspace ? 'mikktspace' : 'own'}): ${r.identical}/${r.corners} ` +
      `corners identical, angle median ${fmt(r.median)} p99 ${fmt(r.p99)} ` +
      `max ${fmt(r.max)} deg, w differs at ${r.wMismatch}, ` +
      `${r.sameBytes ? 'same' : 'different'} bytes after weld` +
      (r.repaired ? ` (${r.repaired} zero tangents repaired)` : '') +
      (problems.length ? `\n  FAIL: ${problems.join('; ')}` : '');
  return {line, ok: problems.length === 0};
}

async function main() {
  const args = process.argv.slice(2);
  let mikktspace = false;
  const jobs = [];
  for (const a of args) {
    if (a === '--mikktspace') {
      mikktspace = true;
    } else if (a.startsWith('-')) {
      console.error(`check-tangent-assets: unknown option ${a}`);
      process.exit(2);
    } else if (fs.statSync(a).isDirectory()) {
      for (const row of readTsv(path.join(a, 'MANIFEST.tsv'))) {
        jobs.push({file: path.join(a, row.file), mikktspace: row.tangents === 'mikktspace'});
      }
    } else {
      jobs.push({file: a, mikktspace: null});
    }
  }
  if (!jobs.length) {
    console.error('usage: node scripts/check-tangent-assets.mjs [--mikktspace] FILE.glb... | DIR');
    process.exit(2);
  }
  const pkgs = loadPackages();
  let failed = 0;
  for (const job of jobs) {
    const {line, ok} = await checkGlb(pkgs, job.file, job.mikktspace ?? mikktspace);
    console.log(line);
    if (!ok) failed++;
  }
  console.log(failed ? `${failed} of ${jobs.length} files FAILED` : `${jobs.length} files OK`);
  process.exit(failed ? 1 : 0);
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  main().catch((e) => {
    console.error(`check-tangent-assets: ${e.stack || e}`);
    process.exit(1);
  });
}
