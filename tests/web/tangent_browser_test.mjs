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
 * three.js in headless Chromium on a normal-mapped asset whose tangents
 * the package's JS encoder predicted (CTest web.tangent_browser).
 *
 * testdata/crane_spot_tangents.glb (MikkTSpace tangents) gets a material
 * with a generated normal texture (a grid of bumps), then glTF-Transform's
 * draco() with registerDracoUv writes it with stock coding, with
 * tangentCompression mikktspace and auto, and, to show that the render
 * depends on the tangents, stock-coded without its TANGENT (three.js then
 * derives tangents from screen-space derivatives). The page of
 * three_browser_test.mjs (three_browser_page.html, served from 127.0.0.1)
 * renders each with one camera on SwiftShader WebGL. Checked:
 *  - the stock GLB decoded by three's own (stock) decoder is the reference;
 *    it is not blank;
 *  - the stock GLB and the tangent-predicted GLBs decoded by the package's
 *    decoder give the reference's pixels exactly;
 *  - the GLB without TANGENT renders other pixels (the tangents matter);
 *  - three's stock decoder fails with a decoding error on every GLB that
 *    requires DRACOUV_attribute_compression (mikktspace always does).
 *
 *   node tests/web/tangent_browser_test.mjs
 *
 * Environment (tests/web contract): DRACO_UV_WEB_PACKAGE, DRACO_UV_SOURCE_DIR
 * (default: two folders up), CHROMIUM (default /usr/bin/chromium; skipped
 * with exit 77 when there is none). Imports puppeteer-core, three and
 * @gltf-transform/* from tests/web/node_modules.
 */
'use strict';

import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import {fileURLToPath} from 'node:url';
import zlib from 'node:zlib';

const kHere = path.dirname(fileURLToPath(import.meta.url));
const kSource = process.env.DRACO_UV_SOURCE_DIR || path.resolve(kHere, '../..');
const kExtension = 'DRACOUV_attribute_compression';
const kTimeoutMs = 150000;
// [name, registerDracoUv options, drop TANGENT]
const kSettings = [
  ['stock', {}, false],
  ['mikktspace', {tangentCompression: {prediction: 'mikktspace'}}, false],
  ['auto', {tangentCompression: {prediction: 'auto'}}, false],
  ['no_tangents', {}, true],
];

let failures = 0;
function check(ok, what) {
  if (!ok) {
    console.log(`FAIL: ${what}`);
    ++failures;
  }
  return ok;
}

function skip(why) {
  console.log(`SKIP: ${why}`);
  process.exit(77);
}

/** A PNG (8-bit RGB) of |width| x |height| pixels from |rgb|. */
function png(width, height, rgb) {
  const table = Array.from({length: 256}, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (bytes) => {
    let c = 0xffffffff;
    for (const b of bytes) c = table[(c ^ b) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type, data) => {
    const out = Buffer.alloc(12 + data.length);
    out.writeUInt32BE(data.length, 0);
    out.write(type, 4, 'latin1');
    data.copy(out, 8);
    out.writeUInt32BE(crc(out.subarray(4, 8 + data.length)), 8 + data.length);
    return out;
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 2, 0, 0, 0], 8);  // 8 bits, RGB, no interlace.
  const rows = Buffer.alloc(height * (1 + 3 * width));
  for (let y = 0; y < height; ++y) {
    rgb.copy(rows, y * (1 + 3 * width) + 1, y * 3 * width,
             (y + 1) * 3 * width);
  }
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header), chunk('IDAT', zlib.deflateSync(rows)),
    chunk('IEND', Buffer.alloc(0))]);
}

/** A tangent-space normal map of a 12 x 12 grid of bumps. */
function bumpNormalMap(size) {
  const rgb = Buffer.alloc(size * size * 3);
  const k = 2 * Math.PI * 12;
  for (let y = 0; y < size; ++y) {
    for (let x = 0; x < size; ++x) {
      const [u, v] = [(x + 0.5) / size, (y + 0.5) / size];
      // Height sin(ku) sin(kv), scaled; the normal is (-dh/du, -dh/dv, 1).
      const du = 0.02 * k * Math.cos(k * u) * Math.sin(k * v);
      const dv = 0.02 * k * Math.sin(k * u) * Math.cos(k * v);
      const length = Math.hypot(du, dv, 1);
      const normal = [-du / length, -dv / length, 1 / length];
      for (let c = 0; c < 3; ++c) {
        rgb[3 * (y * size + x) + c] = Math.round((normal[c] * 0.5 + 0.5) * 255);
      }
    }
  }
  return png(size, size, rgb);
}

/** extensionsRequired of a GLB's JSON chunk. */
function requiredExtensions(glb) {
  const data = Buffer.from(glb);
  const length = data.readUInt32LE(12);
  const json = JSON.parse(data.subarray(20, 20 + length).toString('utf8'));
  return json.extensionsRequired || [];
}

/** The GLBs of every setting, written into |dir|. */
async function makeGlbs(dir) {
  const {NodeIO} = await import('@gltf-transform/core');
  const {draco} = await import('@gltf-transform/functions');
  const {registerDracoUv} = await import('draco3d-uv/gltf-transform');
  const input = path.join(kSource, 'testdata', 'crane_spot_tangents.glb');
  const texture = bumpNormalMap(256);
  const glbs = [];
  for (const [setting, options, dropTangents] of kSettings) {
    const io = await registerDracoUv(new NodeIO(), options);
    const document = await io.read(input);
    const normalTexture = document.createTexture('bumps')
        .setImage(texture).setMimeType('image/png');
    const material = document.createMaterial('bumpy')
        .setBaseColorFactor([0.8, 0.7, 0.6, 1]).setRoughnessFactor(0.5)
        .setMetallicFactor(0).setNormalTexture(normalTexture);
    for (const mesh of document.getRoot().listMeshes()) {
      for (const primitive of mesh.listPrimitives()) {
        primitive.setMaterial(material);
        const tangents = primitive.getAttribute('TANGENT');
        if (dropTangents && tangents) {
          primitive.setAttribute('TANGENT', null);
          tangents.dispose();
        }
      }
    }
    await document.transform(draco());
    const glb = await io.writeBinary(document);
    const name = `crane_spot.${setting}.glb`;
    fs.writeFileSync(path.join(dir, name), glb);
    glbs.push({setting, name, bytes: glb.length,
               marked: requiredExtensions(glb).includes(kExtension)});
  }
  return glbs;
}

const kTypes = {'.html': 'text/html', '.js': 'text/javascript',
                '.mjs': 'text/javascript', '.wasm': 'application/wasm',
                '.glb': 'model/gltf-binary', '.json': 'application/json'};

/** Serves each folder of roots ({name: folder}) as /name/ on 127.0.0.1. */
async function serve(roots) {
  const server = http.createServer((request, response) => {
    const url = new URL(request.url, 'http://127.0.0.1');
    const [, top, ...rest] = decodeURIComponent(url.pathname).split('/');
    const root = roots[top];
    const file = root && path.resolve(root, ...rest);
    if (!file || !(file + path.sep).startsWith(root + path.sep) ||
        !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, {'Content-Type': kTypes[path.extname(file)] ||
                                             'application/octet-stream'});
    fs.createReadStream(file).pipe(response);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return server;
}

const kDecoders = {
  three: '/three/examples/jsm/libs/draco/',
  ours: '/pkg/',
};

async function run(chromium, packageDir, work) {
  const glbs = await makeGlbs(work);
  const server = await serve({
    'page': kHere, 'three': path.join(kHere, 'node_modules', 'three'),
    'pkg': packageDir, 'glb': work});
  const {default: puppeteer} = await import('puppeteer-core');
  let browser;
  try {
    browser = await puppeteer.launch({
      executablePath: chromium, headless: true,
      args: ['--no-sandbox', '--use-angle=swiftshader',
             '--enable-unsafe-swiftshader']});
    const page = await browser.newPage();
    page.on('pageerror', (error) => console.log(`  page error: ${error}`));
    await page.goto(`http://127.0.0.1:${server.address().port}/` +
                    'page/three_browser_page.html');
    await page.waitForFunction('window.pageReady === true', {timeout: 30000});
    let view = null;
    const load = async (glb, decoder) => {
      const result = await page.evaluate(
          (o, v) => window.renderGlb(o, v),
          {glb: `/glb/${glb.name}`, decoderPath: kDecoders[decoder],
           plugin: true}, view);
      console.log(`  ${glb.name} ${decoder}: ` + (result.error ?
          `error "${result.error}"` :
          `sha256 ${result.sha256.slice(0, 16)} model pixels ` +
          `${result.nonBackground}`));
      return result;
    };
    const reference = await load(glbs[0], 'three');
    if (!check(!reference.error, `stock GLB with three's decoder: ` +
               reference.error)) {
      return;
    }
    view = reference.view;
    check(reference.nonBackground > 320 * 240 / 50,
          `reference render nearly blank (${reference.nonBackground} pixels)`);
    for (const glb of glbs) {
      const result = await load(glb, 'ours');
      if (glb.setting === 'no_tangents') {
        check(!result.error && result.sha256 !== reference.sha256,
              `${glb.name}: ${result.error || 'the same pixels as with ' +
                                               'tangents'}`);
        continue;
      }
      check(!result.error && result.sha256 === reference.sha256,
            `${glb.name} with the package's decoder: ` +
            (result.error || 'pixels differ from the stock reference'));
      check(glb.setting !== 'mikktspace' || glb.marked,
            `${glb.name}: ${kExtension} not required`);
      if (glb.marked) {
        const stock = await load(glb, 'three');
        check(/Decoding failed: \S/.test(stock.error || ''),
              `${glb.name} with three's stock decoder: ` +
              (stock.error || 'loaded without an error'));
      }
    }
  } finally {
    if (browser) await browser.close();
    server.close();
  }
  console.log('GLB bytes:');
  for (const glb of glbs) {
    console.log(`  ${glb.name} ${glb.bytes}` +
                (glb.marked ? ` (requires ${kExtension})` : ''));
  }
}

async function main() {
  const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
  if (!fs.existsSync(chromium)) {
    skip(`no Chromium at ${chromium} (apt-get install chromium)`);
  }
  for (const module of ['puppeteer-core', 'three', '@gltf-transform/core',
                        'draco3d-uv']) {
    if (!fs.existsSync(path.join(kHere, 'node_modules', module))) {
      skip(`tests/web/node_modules has no ${module} ` +
           '(tests/web/install-packages.sh installs it)');
    }
  }
  const packageDir = path.resolve(process.env.DRACO_UV_WEB_PACKAGE || '');
  if (!fs.existsSync(path.join(packageDir, 'draco_wasm_wrapper.js'))) {
    skip('DRACO_UV_WEB_PACKAGE is not a package folder');
  }
  const start = Date.now();
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'tangent-browser-'));
  const removeWork = () => fs.rmSync(work, {recursive: true, force: true});
  const watchdog = setTimeout(() => {
    console.error(`FAIL: timed out after ${kTimeoutMs / 1000} s`);
    removeWork();
    process.exit(1);  // puppeteer closes Chromium when the process exits
  }, kTimeoutMs);
  try {
    await run(chromium, packageDir, work);
  } finally {
    clearTimeout(watchdog);
    removeWork();
  }
  const seconds = ((Date.now() - start) / 1000).toFixed(1);
  console.log(`tangent_browser_test: ${failures} failures (${seconds} s)`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(`FAIL: ${error.stack || error}`);
  process.exit(1);
});
