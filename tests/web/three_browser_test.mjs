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
 * three.js in headless Chromium on GLBs written by draco-uv's
 * draco_transcoder: a viewer that only points DRACOLoader.setDecoderPath at
 * the draco3d-uv package folder shows them.
 *
 * For textured glTF assets of Draco's testdata, the native draco_transcoder
 * writes GLBs with stock coding, -uv_pred auto, weighted_multi, auto with
 * -uv_seams context, and laplacian_mv. A page served from 127.0.0.1
 * (three_browser_page.html) loads each with GLTFLoader + DRACOLoader, renders
 * it with one camera at a fixed size on SwiftShader WebGL and returns the
 * pixels. Checked, per asset:
 *  - the stock GLB decoded by three's own (stock) decoder folder is the
 *    reference; it is not blank;
 *  - the stock GLB and every lossless draco-uv GLB decoded by the package's
 *    decoder give the reference's pixels exactly;
 *  - the Laplacian GLB (lossy UVs) renders, not blank, with few pixels
 *    differing from the reference;
 *  - three's stock decoder fails with a decoding error on every GLB that
 *    requires DRACOUV_attribute_compression (no blank success);
 *  - without the package's GLTFLoader plugin (three-plugin.mjs) GLTFLoader
 *    warns 'Unknown extension "DRACOUV_attribute_compression"', with it not.
 * The package's decoder loads its Laplacian part
 * (draco_decoder_laplacian.wasm) only for the Laplacian GLB: the test's
 * server counts its requests (no caching), none for every lossless GLB, at
 * least one for the Laplacian one. Once: the package's gltf/ decoder and its
 * asm.js fallback (setDecoderConfig({type: 'js'})) give the reference's
 * pixels, and gltf/ renders the Laplacian GLB with gltf/'s own part; without
 * the plugin, the Laplacian GLB fails with a decoding error that names the
 * part and the option dracoUvPath, without requesting the part, and renders
 * once the page sets decoderConfig.dracoUvPath itself. Last, on the page's
 * main thread (no worker), the decoder module refuses a Laplacian file until
 * loadDracoUvLaplacian() has loaded the part, then decodes it to the Node
 * package's values.
 *
 *   node tests/web/three_browser_test.mjs
 *
 * Environment (tests/web contract): DRACO_UV_WEB_PACKAGE, DRACO_UV_BUILD_DIR,
 * DRACO_TESTDATA, CHROMIUM (default /usr/bin/chromium; skipped with exit 77
 * when there is none). Imports puppeteer-core from tests/web/node_modules.
 */
'use strict';

import {execFileSync} from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import {createRequire} from 'node:module';
import os from 'node:os';
import path from 'node:path';
import {fileURLToPath} from 'node:url';

const kHere = path.dirname(fileURLToPath(import.meta.url));
const kExtension = 'DRACOUV_attribute_compression';
const kUnknownWarning = `Unknown extension "${kExtension}"`;
// Assets with a base colour texture whose look depends on the UVs.
const kAssets = ['CesiumMilkTruck/glTF/CesiumMilkTruck.gltf',
                 'SphereWithCircleTexture/sphere_with_circle_texture.gltf'];
// UV quantisation bits of every GLB (draco_transcoder's default) but the
// coarse stock one, which the lossy Laplacian is compared against.
const kQt = 10;
const kCoarseQt = kQt - 2;
// [name, draco_transcoder arguments, kind]
const kSettings = [
  ['stock', [], 'lossless'],
  ['auto', ['-uv_pred', 'auto'], 'lossless'],
  ['weighted_multi', ['-uv_pred', 'weighted_multi'], 'lossless'],
  ['auto+context', ['-uv_pred', 'auto', '-uv_seams', 'context'], 'lossless'],
  ['laplacian_mv', ['-uv_pred', 'laplacian_mv'], 'lossy'],
  [`stock_qt${kCoarseQt}`, [], 'coarse'],
];
const kTimeoutMs = 150000;
const kPart = 'draco_decoder_laplacian.wasm';
// Paths the test's server was asked for, in order.
const requests = [];

let failures = 0;
function check(ok, what) {
  if (!ok) {
    console.log(`FAIL: ${what}`);
    ++failures;
  }
  return ok;
}

function env(name) {
  const value = process.env[name];
  if (!value) {
    console.error(`three_browser_test: ${name} is not set`);
    process.exit(1);
  }
  return value;
}

/** extensionsRequired of a GLB's JSON chunk. */
function requiredExtensions(file) {
  const data = fs.readFileSync(file);
  const length = data.readUInt32LE(12);
  const json = JSON.parse(data.subarray(20, 20 + length).toString('utf8'));
  return json.extensionsRequired || [];
}

/** Transcodes every asset with every setting into dir; returns the GLBs. */
function makeGlbs(transcoder, testdata, dir) {
  const glbs = [];
  for (const asset of kAssets) {
    const base = path.basename(asset, '.gltf');
    for (const [setting, args, kind] of kSettings) {
      const qt = kind === 'coarse' ? kCoarseQt : kQt;
      const name = `${base}.${setting.replace('+', '_')}.glb`;
      execFileSync(transcoder, ['-i', path.join(testdata, asset),
                                '-o', path.join(dir, name),
                                '-qt', String(qt), ...args],
                   {stdio: ['ignore', 'ignore', 'inherit']});
      const file = path.join(dir, name);
      glbs.push({asset: base, setting, kind, name,
                 bytes: fs.statSync(file).size,
                 marked: requiredExtensions(file).includes(kExtension)});
    }
  }
  return glbs;
}

const kTypes = {'.html': 'text/html', '.js': 'text/javascript',
                '.mjs': 'text/javascript', '.wasm': 'application/wasm',
                '.glb': 'model/gltf-binary', '.json': 'application/json'};

/**
 * Serves each folder of roots ({name: folder}) as /name/ on 127.0.0.1, at a
 * port the system picks.
 */
async function serve(roots) {
  const server = http.createServer((request, response) => {
    const url = new URL(request.url, 'http://127.0.0.1');
    requests.push(url.pathname);
    const [, top, ...rest] = decodeURIComponent(url.pathname).split('/');
    const root = roots[top];
    const file = root && path.resolve(root, ...rest);
    if (!file || !(file + path.sep).startsWith(root + path.sep) ||
        !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      response.writeHead(404).end();
      return;
    }
    // No caching, so that every load of the Laplacian part is a request.
    response.writeHead(200, {'Content-Type': kTypes[path.extname(file)] ||
                                             'application/octet-stream',
                             'Cache-Control': 'no-store'});
    fs.createReadStream(file).pipe(response);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return server;
}

/**
 * How far a render is from the reference: the fraction of the reference's
 * model pixels that differ, and the mean over them of the largest colour
 * channel difference (0-255).
 */
function difference(reference, other) {
  const a = Buffer.from(reference.pixels, 'base64');
  const b = Buffer.from(other.pixels, 'base64');
  let differing = 0;
  let sum = 0;
  for (let i = 0; i < a.length; i += 4) {
    const d = Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]),
                       Math.abs(a[i + 2] - b[i + 2]));
    differing += d > 0;
    sum += d;
  }
  const model = Math.max(reference.nonBackground, 1);
  return {differing: differing / model, mean: sum / model};
}

/**
 * Renders in the page; prints one line; returns the page's result with
 * partRequests, how often the server was asked for the Laplacian part.
 */
async function render(page, label, options, view) {
  const first = requests.length;
  const result = await page.evaluate(
      (o, v) => window.renderGlb(o, v), options, view || null);
  const folder = options.dracoUvPath || options.decoderPath;
  result.partRequests =
      requests.slice(first).filter((p) => p.endsWith(`/${kPart}`)).length;
  result.partRequestsElsewhere = requests.slice(first).filter(
      (p) => p.endsWith(`/${kPart}`) && p !== `${folder}${kPart}`).length;
  const what = result.error ? `error "${result.error}"` :
      `sha256 ${result.sha256.slice(0, 16)} model pixels ${result.nonBackground}`;
  console.log(`  ${label}: ${what}; ${kPart} requested ` +
              `${result.partRequests} times`);
  return result;
}

const kDecoders = {
  three: {decoderPath: '/three/examples/jsm/libs/draco/'},
  ours: {decoderPath: '/pkg/'},
  oursGltf: {decoderPath: '/pkg/gltf/'},
  oursAsmjs: {decoderPath: '/pkg/', asmjs: true},
  oursWithPath: {decoderPath: '/pkg/', dracoUvPath: '/pkg/'},
};

/**
 * Loads one GLB with the package's decoder (the coarse stock GLB with three's)
 * and, unless its coding is stock by construction, with three's stock
 * decoder. Returns its difference to the reference when it is lossy.
 */
async function checkGlb(t, glb) {
  // Only -uv_pred auto may keep stock coding (and write no marker).
  const stockIds = glb.setting === 'stock' || glb.kind === 'coarse';
  check(glb.setting === 'auto' || glb.marked !== stockIds,
        `${glb.name}: ${kExtension} ${glb.marked ? '' : 'not '}required`);
  const result = await t.load(glb, glb.kind === 'coarse' ? 'three' : 'ours');
  check(!result.warnings.some((w) => w.includes(kUnknownWarning)),
        `${glb.name}: "${kUnknownWarning}" with the plugin registered`);
  check(glb.kind === 'lossy' ? result.partRequests > 0 :
                               result.partRequests === 0,
        `${glb.name}: ${kPart} requested ${result.partRequests} times`);
  let lossy;
  if (glb.kind === 'lossless') {
    t.same(result, `${glb.name} with the package's decoder`);
  } else if (check(!result.error, `${glb.name}: ${result.error}`)) {
    lossy = difference(t.reference, result);
    check(result.nonBackground === t.reference.nonBackground,
          `${glb.name}: ${result.nonBackground} model pixels, the ` +
          `reference ${t.reference.nonBackground}`);
  }
  if (stockIds) return lossy;
  const stockDecoder = await t.load(glb, 'three');
  if (glb.marked) {
    check(/Decoding failed: \S/.test(stockDecoder.error || ''),
          `${glb.name} with three's stock decoder: ` +
          (stockDecoder.error || 'loaded without an error'));
  } else {
    // Without the marker the file is stock Draco: three's decoder reads it.
    t.same(stockDecoder, `${glb.name} (stock ids) with three's decoder`);
  }
  return lossy;
}

/**
 * The checks of one asset's GLBs (with once: also gltf/ and asm.js). Prints
 * the Laplacian's and the coarse stock GLB's difference to the reference.
 */
async function checkAsset(page, glbs, once) {
  const asset = glbs[0].asset;
  const t = {};
  t.load = (glb, decoder, plugin = true) => render(
      page, `${glb.name} ${decoder}${plugin ? '' : ' (no plugin)'}`,
      {glb: `/glb/${glb.name}`, plugin, ...kDecoders[decoder]},
      t.reference && t.reference.view);
  t.reference = await t.load(glbs[0], 'three');
  if (!check(!t.reference.error, `${asset}: stock GLB with three's ` +
             `decoder: ${t.reference.error}`)) {
    return;
  }
  check(t.reference.nonBackground > 320 * 240 / 50, `${asset}: reference ` +
        `render nearly blank (${t.reference.nonBackground} model pixels)`);
  t.same = (result, what) => check(
      !result.error && result.sha256 === t.reference.sha256,
      `${what}: ${result.error || 'pixels differ from the stock reference'}`);
  const lossy = {};
  for (const glb of glbs) {
    const figures = await checkGlb(t, glb);
    if (figures) lossy[glb.kind] = figures;
  }
  for (const [kind, {differing, mean}] of Object.entries(lossy)) {
    console.log(`    ${kind}: ${(100 * differing).toFixed(2)}% of the ` +
                `model pixels differ, by ${mean.toFixed(3)} on average`);
  }
  check(lossy.lossy && lossy.coarse && lossy.lossy.mean <= lossy.coarse.mean,
        `${asset}: the Laplacian (qt ${kQt}) renders further from the ` +
        `reference than stock coding at qt ${kCoarseQt}`);
  const marked = glbs.find((g) => g.kind === 'lossless' && g.marked);
  const bare = await t.load(marked, 'ours', false);
  t.same(bare, `${marked.name} without the plugin`);
  check(bare.warnings.some((w) => w.includes(kUnknownWarning)),
        `${marked.name}: no "${kUnknownWarning}" warning without the plugin`);
  if (once) {
    t.same(await t.load(marked, 'oursGltf'),
           `${marked.name} with the package's gltf/ decoder`);
    t.same(await t.load(marked, 'oursAsmjs'),
           `${marked.name} with the package's asm.js decoder`);
    const lossy = glbs.find((g) => g.kind === 'lossy');
    const viaGltf = await t.load(lossy, 'oursGltf');
    check(!viaGltf.error && viaGltf.partRequests > 0 &&
              viaGltf.partRequestsElsewhere === 0 &&
              viaGltf.nonBackground === t.reference.nonBackground,
          `${lossy.name} with the package's gltf/ decoder: ` +
          (viaGltf.error || `${viaGltf.nonBackground} model pixels, ` +
           `${kPart} requested ${viaGltf.partRequests} times, ` +
           `${viaGltf.partRequestsElsewhere} of them outside gltf/`));
    const unaided = await t.load(lossy, 'ours', false);
    check(/Decoding failed: .*draco_decoder_laplacian\.wasm.*dracoUvPath/
              .test(unaided.error || '') && unaided.partRequests === 0,
          `${lossy.name} without the plugin: ` +
          (unaided.error || 'loaded without an error') +
          `; ${kPart} requested ${unaided.partRequests} times`);
    const configured = await t.load(lossy, 'oursWithPath', false);
    check(!configured.error && configured.partRequests > 0 &&
              configured.nonBackground === t.reference.nonBackground,
          `${lossy.name} without the plugin, decoderConfig.dracoUvPath ` +
          `set: ${configured.error || `${configured.nonBackground} ` +
          `model pixels, ${kPart} requested ${configured.partRequests} times`}`);
  }
}

/**
 * Decodes a Draco file with a decoder module (page or Node); returns
 * {uv: its first TEX_COORD as floats} or {error}. Runs in the page as source
 * text, so it uses nothing outside itself.
 */
function decodeUv(draco, bytes) {
  const decoder = new draco.Decoder();
  const mesh = new draco.Mesh();
  try {
    const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
    if (!status.ok()) return {error: status.error_msg()};
    const att = decoder.GetAttribute(
        mesh, decoder.GetAttributeId(mesh, draco.TEX_COORD));
    const count = mesh.num_points() * 2;
    const ptr = draco._malloc(count * 4);
    decoder.GetAttributeDataArrayForAllPoints(mesh, att, draco.DT_FLOAT32,
                                              count * 4, ptr);
    const uv = Array.from(new Float32Array(draco.HEAPF32.buffer, ptr, count));
    draco._free(ptr);
    return {uv};
  } finally {
    draco.destroy(mesh);
    draco.destroy(decoder);
  }
}

/**
 * In the page, on its main thread, with no worker: loads the package's
 * decoder from a <script> as a page using DracoDecoderModule directly does,
 * decodes a lossless file, then a Laplacian one (which must fail, naming
 * loadDracoUvLaplacian(), without fetching the part), awaits
 * loadDracoUvLaplacian() and decodes it again. Returns each step's result
 * and how many requests for the part each made.
 */
async function mainThreadSteps(page, files) {
  const source = `(async (files, decodeUv) => {
    await new Promise((resolve, reject) => {
      const script = document.createElement('script');
      script.src = '/pkg/draco_wasm_wrapper.js';
      script.onload = resolve;
      script.onerror = () => reject(new Error('cannot load the wrapper'));
      document.head.appendChild(script);
    });
    const draco = await DracoDecoderModule();
    const read = async (url) =>
        new Int8Array(await (await fetch(url)).arrayBuffer());
    const lossless = decodeUv(draco, await read(files.lossless));
    const lossyBytes = await read(files.lossy);
    const refused = decodeUv(draco, lossyBytes);
    await draco.loadDracoUvLaplacian();
    const lossy = decodeUv(draco, lossyBytes);
    return {lossless: lossless.error || lossless.uv.length, refused, lossy};
  })(${JSON.stringify(files)}, ${decodeUv.toString()})`;
  const first = requests.length;
  const result = await page.evaluate(source);
  result.partRequests = requests.slice(first)
      .filter((p) => p.endsWith(`/${kPart}`)).length;
  return result;
}

/**
 * The package's decoder on a page's main thread: lossless files need no
 * part; a Laplacian file needs loadDracoUvLaplacian() first (a clear error
 * before, one request for the part), then decodes to the values the Node
 * package gives.
 */
async function checkMainThread(page, packageDir, goldenDir) {
  const lossy = fs.readdirSync(path.join(goldenDir, 'lossy'))
      .filter((f) => f.endsWith('.laplacian_mv.drc')).sort()[0];
  const lossless = fs.readdirSync(goldenDir)
      .filter((f) => f.endsWith('.weighted.drc')).sort()[0];
  const got = await mainThreadSteps(
      page, {lossless: `/golden/${lossless}`, lossy: `/golden/lossy/${lossy}`});
  console.log(`main thread: ${lossless} ${got.lossless} UV values; ` +
              `${lossy} before loadDracoUvLaplacian(): ` +
              `${got.refused.error || 'decoded'}; after: ` +
              `${got.lossy.error || `${got.lossy.uv.length} UV values`}; ` +
              `${kPart} requested ${got.partRequests} times`);
  check(typeof got.lossless === 'number' && got.lossless > 0,
        `main thread: ${lossless}: ${got.lossless}`);
  check(/main thread.*loadDracoUvLaplacian\(\)/.test(got.refused.error || '') &&
            !/dracoUvPath/.test(got.refused.error),
        `main thread: ${lossy} before loadDracoUvLaplacian(): ` +
        (got.refused.error || 'decoded'));
  check(got.partRequests === 1,
        `main thread: ${kPart} requested ${got.partRequests} times, not once`);
  const require = createRequire(import.meta.url);
  const draco = await require(path.join(packageDir, 'draco3d.js'))
      .createDecoderModule();
  const node = decodeUv(draco, fs.readFileSync(path.join(goldenDir, 'lossy', lossy)));
  check(!got.lossy.error && node.uv &&
            JSON.stringify(got.lossy.uv) === JSON.stringify(node.uv),
        `main thread: ${lossy} after loadDracoUvLaplacian(): ` +
        (got.lossy.error || 'values differ from the Node package\'s'));
}

async function launch(chromium, url) {
  const {default: puppeteer} = await import('puppeteer-core');
  const browser = await puppeteer.launch({
    executablePath: chromium, headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader',
           '--enable-unsafe-swiftshader']});
  const page = await browser.newPage();
  page.on('pageerror', (error) => console.log(`  page error: ${error}`));
  await page.goto(url);
  await page.waitForFunction('window.pageReady === true', {timeout: 30000});
  return {browser, page};
}

/**
 * What the test needs, from the environment; exits 77 (skip) without
 * Chromium or tests/web/node_modules, 1 without a complete package.
 */
function prerequisites() {
  const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
  if (!fs.existsSync(chromium)) {
    console.log(`SKIP: no Chromium at ${chromium} (apt-get install chromium)`);
    process.exit(77);
  }
  for (const module of ['puppeteer-core', 'three']) {
    if (!fs.existsSync(path.join(kHere, 'node_modules', module))) {
      console.log(`SKIP: tests/web/node_modules has no ${module} ` +
                  '(tests/web/install-packages.sh installs it)');
      process.exit(77);
    }
  }
  const packageDir = path.resolve(env('DRACO_UV_WEB_PACKAGE'));
  for (const file of ['draco_wasm_wrapper.js', 'three-plugin.mjs',
                      'gltf/draco_wasm_wrapper.js', 'draco_decoder.js',
                      kPart, `gltf/${kPart}`]) {
    if (!fs.existsSync(path.join(packageDir, file))) {
      console.error(`three_browser_test: ${packageDir} has no ${file} ` +
                    '(./draco-uv.sh web builds the package)');
      process.exit(1);
    }
  }
  return {chromium, packageDir, testdata: env('DRACO_TESTDATA'),
          goldenDir: path.join(env('DRACO_UV_SOURCE_DIR'), 'testdata', 'golden'),
          transcoder: path.join(env('DRACO_UV_BUILD_DIR'), 'draco',
                                'draco_transcoder')};
}

async function run({chromium, packageDir, testdata, transcoder, goldenDir},
                   work) {
  const glbs = makeGlbs(transcoder, testdata, work);
  const server = await serve({
    'page': kHere, 'three': path.join(kHere, 'node_modules', 'three'),
    'pkg': packageDir, 'glb': work, 'golden': goldenDir});
  let browser;
  try {
    const url = `http://127.0.0.1:${server.address().port}/` +
                'page/three_browser_page.html';
    let page;
    ({browser, page} = await launch(chromium, url));
    let once = true;
    for (const asset of new Set(glbs.map((g) => g.asset))) {
      console.log(asset);
      await checkAsset(page, glbs.filter((g) => g.asset === asset), once);
      once = false;
    }
    await checkMainThread(page, packageDir, goldenDir);
  } finally {
    if (browser) await browser.close();
    server.close();
  }
  console.log('GLB bytes:');
  for (const glb of glbs) {
    const marker = glb.marked ? ` (requires ${kExtension})` : '';
    console.log(`  ${glb.name} ${glb.bytes}${marker}`);
  }
}

async function main() {
  const config = prerequisites();
  const start = Date.now();
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'three-browser-'));
  const removeWork = () => fs.rmSync(work, {recursive: true, force: true});
  const watchdog = setTimeout(() => {
    console.error(`FAIL: timed out after ${kTimeoutMs / 1000} s`);
    removeWork();
    process.exit(1);  // puppeteer closes Chromium when the process exits
  }, kTimeoutMs);
  try {
    await run(config, work);
  } finally {
    clearTimeout(watchdog);
    removeWork();
  }
  const seconds = ((Date.now() - start) / 1000).toFixed(1);
  console.log(`three_browser_test: ${failures} failures (${seconds} s)`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(`FAIL: ${error.stack || error}`);
  process.exit(1);
});
