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
 * What TANGENT attributes cost stock Draco: every asset is transcoded by
 * draco_transcoder (without draco-uv's options, so byte-identical to Draco
 * 1.5.5) at -qp 14 -qt 12 -qn 10 -cl 7 with -qtg 8 and -qtg 12, and a copy
 * of it without TANGENT (removed with glTF-Transform) at the same settings.
 * An asset's Draco bytes are the bufferViews its primitives'
 * KHR_draco_mesh_compression extensions reference (each counted once);
 * TANGENT bytes are the difference with and without TANGENT, bits per
 * vertex divide them by the vertices of the primitives that have TANGENT
 * (primitives with the same accessors counted once, as the transcoder
 * encodes them once). Without TANGENT the transcoder may merge vertices
 * that differed only in their tangent, so the difference includes what the
 * tangents cost the connectivity and the other attributes.
 * Prints a Markdown table; the transcodes go to a temporary folder that is
 * removed afterwards.
 *
 *   node scripts/tangent-stock-bytes.mjs [--transcoder PATH] [DIR | FILE.glb...]
 *
 * DIR (default build/tangent-assets) is a folder of
 * scripts/make-tangent-assets.mjs with its MANIFEST.tsv. PATH defaults to
 * build/draco/draco_transcoder. Needs tests/web's npm packages:
 * (cd tests/web && npm ci --ignore-scripts).
 */

import {execFileSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {pathToFileURL} from 'node:url';

import {distinctPrimitives, kRepo, loadPackages, readTsv} from './make-tangent-assets.mjs';

const kFlags = ['-qp', '14', '-qt', '12', '-qn', '10', '-cl', '7'];
const kTangentBits = [8, 12];

/** The JSON chunk of a GLB. */
function glbJson(bytes) {
  if (bytes.readUInt32LE(0) !== 0x46546c67) throw new Error('not a GLB');
  const length = bytes.readUInt32LE(12);
  if (bytes.readUInt32LE(16) !== 0x4e4f534a) throw new Error('GLB without JSON chunk');
  return JSON.parse(bytes.subarray(20, 20 + length).toString('utf8'));
}

/**
 * Bytes of the Draco buffers of a transcoded GLB, and whether some Draco
 * primitive carries TANGENT.
 */
function dracoBytes(file) {
  const json = glbJson(fs.readFileSync(file));
  const views = new Set();
  let primitives = 0, withTangent = 0;
  for (const mesh of json.meshes || []) {
    for (const prim of mesh.primitives) {
      const ext = prim.extensions?.KHR_draco_mesh_compression;
      if (!ext) throw new Error(`${file}: a primitive without Draco compression`);
      views.add(ext.bufferView);
      primitives++;
      if ('TANGENT' in ext.attributes) withTangent++;
    }
  }
  let bytes = 0;
  for (const v of views) bytes += json.bufferViews[v].byteLength;
  return {bytes, primitives, withTangent};
}

function transcode(transcoder, input, output, tangentBits) {
  execFileSync(transcoder, ['-i', input, '-o', output, ...kFlags, '-qtg', String(tangentBits)],
               {stdio: ['ignore', 'ignore', 'pipe']});
}

async function main() {
  const args = process.argv.slice(2);
  let transcoder = path.join(kRepo, 'build', 'draco', 'draco_transcoder');
  const inputs = [];
  for (let i = 0; i < args.length; i++) {
    if (args[i] === '--transcoder' && i + 1 < args.length) transcoder = args[++i];
    else if (args[i].startsWith('-')) {
      console.error('usage: node scripts/tangent-stock-bytes.mjs [--transcoder PATH] [DIR | FILE.glb...]');
      process.exit(2);
    } else inputs.push(args[i]);
  }
  if (!inputs.length) inputs.push(path.join(kRepo, 'build', 'tangent-assets'));
  if (!fs.existsSync(transcoder)) {
    console.error(`tangent-stock-bytes: no ${transcoder} (build it, or --transcoder PATH)`);
    process.exit(1);
  }
  const assets = [];
  for (const a of inputs) {
    if (fs.statSync(a).isDirectory()) {
      for (const row of readTsv(path.join(a, 'MANIFEST.tsv'))) {
        assets.push({name: row.name, file: path.join(a, row.file), tangents: row.tangents});
      }
    } else {
      assets.push({name: path.basename(a, '.glb'), file: a, tangents: ''});
    }
  }

  const pkgs = loadPackages();
  const io = new pkgs.core.NodeIO();
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'tangent-stock-bytes-'));
  const head = ['asset', 'tangents', 'vertices', 'Draco bytes without TANGENT'];
  for (const b of kTangentBits) {
    head.push(`Draco bytes, -qtg ${b}`, `TANGENT bytes, -qtg ${b}`, `bits/vertex, -qtg ${b}`);
  }
  const lines = [`| ${head.join(' | ')} |`, `| --- | --- |${' ---: |'.repeat(head.length - 2)}`];
  try {
    for (const asset of assets) {
      const doc = await io.read(asset.file);
      let vertices = 0;
      for (const prim of distinctPrimitives(doc)) {
        if (prim.getAttribute('TANGENT')) vertices += prim.getAttribute('POSITION').getCount();
      }
      for (const mesh of doc.getRoot().listMeshes()) {
        for (const prim of mesh.listPrimitives()) {
          const t = prim.getAttribute('TANGENT');
          if (!t) continue;
          prim.setAttribute('TANGENT', null);
          if (t.listParents().length === 1) t.dispose();
        }
      }
      const without = path.join(tmp, `${asset.name}.notangent.glb`);
      await io.write(without, doc);
      const out = path.join(tmp, 'out.glb');
      transcode(transcoder, without, out, kTangentBits[0]);
      const base = dracoBytes(out);
      if (base.withTangent) throw new Error(`${asset.name}: TANGENT left in the copy`);
      const row = [asset.name, asset.tangents, vertices, base.bytes];
      for (const b of kTangentBits) {
        transcode(transcoder, asset.file, out, b);
        const d = dracoBytes(out);
        if (!d.withTangent) throw new Error(`${asset.name}: no Draco TANGENT at -qtg ${b}`);
        const t = d.bytes - base.bytes;
        row.push(d.bytes, `${t} (${(100 * t / d.bytes).toFixed(0)} %)`,
                 (8 * t / vertices).toFixed(1));
      }
      lines.push(`| ${row.join(' | ')} |`);
      console.error(`${asset.name} done`);
    }
  } finally {
    fs.rmSync(tmp, {recursive: true, force: true});
  }
  console.log(`Stock draco_transcoder ${kFlags.join(' ')}; TANGENT bytes = Draco bytes ` +
              'with TANGENT minus without (share of the Draco bytes with TANGENT).\n');
  console.log(lines.join('\n'));
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  main().catch((e) => {
    console.error(`tangent-stock-bytes: ${e.stack || e}`);
    process.exit(1);
  });
}
