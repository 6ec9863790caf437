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
 * glTF-Transform (the pinned @gltf-transform/* 4.5.1) with draco3d-uv's
 * gltf-transform.mjs and gltf-transform.config.mjs.
 *
 * Each asset of gltf_checks.mjs is first written as an uncompressed GLB,
 * then read and written with the draco() transform by an I/O set up with
 * registerDracoUv(): without texture coordinate options (the reference), with
 * npm draco3d 1.5.9's encoder, and with -uv_pred auto, auto + -uv_seams
 * context and weighted_multi. Checked, per asset and setting:
 *  - the GLB reads back with the package's decoder to the reference's
 *    triangles exactly (every attribute; lossless coders, same
 *    quantisation); npm draco3d's encoder writes the reference's bytes;
 *  - DRACOUV_attribute_compression is in extensionsUsed and
 *    extensionsRequired exactly when npm draco3d's decoder fails on some
 *    Draco buffer of the file; never without texture coordinate options,
 *    never for Box (no TEXCOORD); with weighted_multi and auto + context
 *    always for the large textured assets (auto may keep stock ids);
 *  - every draco-uv coding that marks the file makes the large textured
 *    assets' Draco buffers smaller than the reference's, and their files too
 *    but for the marker's JSON; auto's Draco buffers are never larger on any
 *    asset;
 *  - auto (stock seams) pays for the marker: on every asset its GLB is never
 *    larger than the reference's, and smaller when marked, and so are its
 *    GLB and its .gltf (JSON, .bin and images) under three more draco()
 *    settings (gltf-pipeline's quantisation at speeds 3 and 0, where Fox's
 *    draco-uv saving is below the marker's cost; speed 8), some marked;
 *  - glTF-Transform fails on a marked file with an error: with npm draco3d's
 *    decoder ("Decoding failure") and without the extension registered
 *    ("Missing required extension");
 *  - the read-back Document (which carries the extension) written again
 *    without texture coordinate options, or without Draco, is not marked;
 *  - the native draco_transcoder reads the marked files;
 *  - files of the native draco_transcoder -uv_pred auto -uv_seams context
 *    read back to the native stock transcode's triangles.
 * The CLI (node_modules/.bin/gltf-transform) with --config
 * node_modules/draco3d-uv/gltf-transform.config.mjs: `draco` writes a marked
 * file smaller than the CLI's own (npm draco3dgltf) with the same triangles,
 * DRACO_UV_PRED=draco DRACO_UV_SEAMS=draco DRACO_TANGENT_PRED=draco an
 * unmarked one, Box an unmarked
 * one; `inspect` reads the marked file with the config and fails without it;
 * an unknown DRACO_UV_PRED fails naming the valid names.
 * Prints the sizes (bytes) per asset and setting.
 *
 *   node tests/web/gltf_transform_test.mjs
 *
 * Environment (tests/web contract): DRACO_UV_WEB_PACKAGE, DRACO_TESTDATA,
 * DRACO_UV_BUILD_DIR (native checks skipped when its tools are missing), and
 * tests/web/node_modules from tests/web/install-packages.sh.
 */
'use strict';

import {execFileSync, spawnSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {fileURLToPath} from 'node:url';
import {ASSETS, LARGE_ASSETS, MARKER, UV_SETTINGS, check, checkNotLarger,
        checkSmaller, countUndecodable, dracoBuffers, environment,
        geometryDigests, hasMarker, hasTexCoords, parseGlb} from
  './gltf_checks.mjs';

const kHere = path.dirname(fileURLToPath(import.meta.url));
const env = environment(kHere);

const {NodeIO} = await import('@gltf-transform/core');
const {KHRDracoMeshCompression} = await import('@gltf-transform/extensions');
const {draco} = await import('@gltf-transform/functions');
const {default: npmDraco} = await import('draco3d');
const {default: ourDraco} = await import('draco3d-uv');
const {registerDracoUv, DracoUvAttributeCompression} =
  await import('draco3d-uv/gltf-transform');

const work = fs.mkdtempSync(path.join(os.tmpdir(), 'gltf-transform-test-'));
let failures = 0;

function fail(message) {
  console.log(`FAIL: ${message}`);
  failures++;
}

/** Runs check |fn|; a thrown Error is one failure. */
async function expect(what, fn) {
  try {
    await fn();
  } catch (error) {
    fail(`${what}: ${error.message}`);
  }
}

async function throwsWith(fn, pattern) {
  try {
    await fn();
  } catch (error) {
    return pattern.test(error.message) ? '' :
      `failed with "${error.message}", expected ${pattern}`;
  }
  return 'did not fail';
}

function sum(buffers) {
  return buffers.reduce((total, b) => total + b.length, 0);
}

/** Uncompressed GLBs of the assets, written by glTF-Transform. */
async function makeInputs() {
  const io = new NodeIO();
  const inputs = [];
  for (const asset of ASSETS) {
    const document = await io.read(path.join(env.testdata, asset.file));
    check(hasTexCoords(document) === asset.uv,
          `${asset.name}: TEXCOORD presence is not ${asset.uv}`);
    const file = path.join(work, `${asset.name}.glb`);
    await io.write(file, document);
    inputs.push({...asset, glb: file});
  }
  return inputs;
}

async function encodeAll(inputs, settings) {
  const results = new Map();  // "asset/setting" -> {glb, json, decoded, ...}
  for (const setting of settings) {
    const io = await registerDracoUv(new NodeIO(), setting.options);
    for (const input of inputs) {
      const document = await io.read(input.glb);
      await document.transform(draco());
      const glb = await io.writeBinary(document);
      const file = path.join(work, `${input.name}.${setting.name}.glb`);
      fs.writeFileSync(file, glb);
      results.set(`${input.name}/${setting.name}`,
                  {glb, file, json: parseGlb(glb).json,
                   dracoBytes: sum(dracoBuffers(glb))});
    }
  }
  return results;
}

async function checkOutputs(inputs, settings, results, ctx) {
  for (const input of inputs) {
    const reference = results.get(`${input.name}/stock`);
    for (const setting of settings) {
      const result = results.get(`${input.name}/${setting.name}`);
      await expect(`${input.name} ${setting.name}`, () => {
        result.marked = hasMarker(result.json);
        const {failed, total} = countUndecodable(ctx.npmDecoder, result.glb);
        check(total > 0, 'no Draco buffers');
        check(result.marked === (failed > 0),
              `marker ${result.marked} but npm draco3d fails on ` +
              `${failed} of ${total} Draco buffers`);
        if (!setting.uv || !input.uv) {
          check(!result.marked, 'marked without draco-uv coding');
        }
        if (setting.name === 'npm-draco3d') {
          check(Buffer.from(result.glb).equals(Buffer.from(reference.glb)),
                'npm draco3d\'s encoder wrote other bytes than the ' +
                'package without options');
        }
        if (setting.forcesIds && input.large) {
          check(result.marked, 'not marked (no primitive used draco-uv)');
        }
        if (setting.name === 'auto') {
          check(result.dracoBytes <= reference.dracoBytes,
                `auto: Draco buffers of ${result.dracoBytes} bytes, ` +
                `stock coding's ${reference.dracoBytes}`);
        }
        if (setting.uv && input.large &&
            (result.marked || !setting.neverLarger)) {
          checkSmaller(result.glb, reference.glb, result.marked);
        }
        if (setting.neverLarger) {
          checkNotLarger(result.glb, reference.glb, result.marked);
        }
      });
    }
  }
}

// draco() settings besides its defaults (speed 5, -qp 14 -qt 12) under
// which auto must pay for the marker too: gltf-pipeline's default
// quantisation at its speed and at the slowest speed (where Fox's draco-uv
// saving is smaller than the marker), and speed 8.
const DRACO_VARIANTS = [
  {encodeSpeed: 3, decodeSpeed: 3, quantizePosition: 11, quantizeTexcoord: 10,
   quantizeNormal: 8},
  {encodeSpeed: 0, decodeSpeed: 0, quantizePosition: 11, quantizeTexcoord: 10},
  {encodeSpeed: 8, decodeSpeed: 8},
];

/** The bytes of all files in |dir|. */
function folderBytes(dir) {
  return fs.readdirSync(dir).reduce(
      (total, name) => total + fs.statSync(path.join(dir, name)).size, 0);
}

/**
 * Writes each asset under each of DRACO_VARIANTS with stock coding and with
 * auto as GLB and as .gltf with its files; auto's are never larger.
 */
async function checkAutoPaysForTheMarker(inputs, ctx) {
  const ios = {
    stock: ctx.ourIO,
    auto: await registerDracoUv(new NodeIO(), {texCoordCompression:
                                               {prediction: 'auto'}}),
  };
  let marked = 0;
  for (const [index, variant] of DRACO_VARIANTS.entries()) {
    for (const input of inputs) {
      const sizes = {};
      for (const [name, io] of Object.entries(ios)) {
        const document = await io.read(input.glb);
        await document.transform(draco(variant));
        const glb = await io.writeBinary(document);
        const dir = path.join(work, `${input.name}.${index}.${name}`);
        fs.mkdirSync(dir);
        await io.write(path.join(dir, 'asset.gltf'), document);
        sizes[name] = {glb, gltf: folderBytes(dir),
                       marked: hasMarker(parseGlb(glb).json)};
      }
      marked += sizes.auto.marked ? 1 : 0;
      await expect(`${input.name} auto ${JSON.stringify(variant)}`, () => {
        checkNotLarger(sizes.auto.glb, sizes.stock.glb, sizes.auto.marked);
        checkNotLarger(sizes.auto.gltf, sizes.stock.gltf, sizes.auto.marked);
      });
    }
  }
  await expect('auto under draco() variants', () =>
    check(marked > 0, 'no file was marked: the check compared stock files'));
}

async function checkReadBack(inputs, settings, results, ctx) {
  for (const input of inputs) {
    for (const setting of settings) {
      const what = `${input.name} ${setting.name}`;
      const result = results.get(`${input.name}/${setting.name}`);
      await expect(`${what} reads back`, async () => {
        const document = await ctx.ourIO.readBinary(result.glb);
        result.digests = geometryDigests(document);
        const reference = results.get(`${input.name}/stock`).digests;
        if (reference) {
          check(JSON.stringify(result.digests) === JSON.stringify(reference),
                `triangles differ from stock coding's:\n  ` +
                `${result.digests}\n  ${reference}`);
        }
        if (!result.marked) {
          return;
        }
        let error = await throwsWith(() => ctx.npmIO.readBinary(result.glb),
                                     /Decoding failure/);
        check(!error, `npm draco3d's decoder: ${error}`);
        error = await throwsWith(() => ctx.plainIO.readBinary(result.glb),
                                 /Missing required extension, "DRACOUV/);
        check(!error, `without the extension: ${error}`);
        // Written again: without options, and without Draco.
        const again = parseGlb(await ctx.ourIO.writeBinary(document)).json;
        check(!hasMarker(again), 'marked when written again without options');
        document.disposeExtension('KHR_draco_mesh_compression');
        const plain = parseGlb(await ctx.ourIO.writeBinary(document)).json;
        check(!hasMarker(plain), 'marked when written without Draco');
      });
    }
  }
}

function nativeTool(name) {
  const file = env.buildDir && path.join(env.buildDir, 'draco', name);
  return file && fs.existsSync(file) ? file : null;
}

async function checkNative(inputs, results, ctx) {
  const transcoder = nativeTool('draco_transcoder');
  if (!transcoder) {
    console.log('native checks skipped: no draco_transcoder in ' +
                'DRACO_UV_BUILD_DIR');
    return;
  }
  for (const input of inputs) {
    const ours = results.get(`${input.name}/auto+context`);
    await expect(`${input.name}: draco_transcoder reads ours`, () => {
      execFileSync(transcoder, ['-i', ours.file, '-o',
                                path.join(work, 'native_read.glb')],
                   {stdio: 'pipe'});
    });
    await expect(`${input.name}: native -uv_pred auto reads back`,
                 async () => {
      const digests = [];
      for (const flags of [[], ['-uv_pred', 'auto', '-uv_seams', 'context']]) {
        const out = path.join(work, `${input.name}.native.glb`);
        execFileSync(transcoder, ['-i', input.glb, '-o', out, ...flags],
                     {stdio: 'pipe'});
        digests.push(geometryDigests(await ctx.ourIO.read(out)));
      }
      check(JSON.stringify(digests[0]) === JSON.stringify(digests[1]),
            'triangles differ from the native stock transcode\'s');
    });
  }
}

function runCli(args, extraEnv = {}) {
  const cli = path.join(kHere, 'node_modules', '.bin', 'gltf-transform');
  return spawnSync(cli, args,
                   {cwd: kHere, encoding: 'utf8',
                    env: {...process.env, ...extraEnv}});
}

async function checkCli(inputs, ctx) {
  const config = ['--config',
                  'node_modules/draco3d-uv/gltf-transform.config.mjs'];
  const stockEnv = {DRACO_UV_PRED: 'draco', DRACO_UV_SEAMS: 'draco',
                    DRACO_TANGENT_PRED: 'draco'};
  for (const input of inputs.filter((i) => i.large || !i.uv)) {
    const out = (tag) => path.join(work, `${input.name}.cli.${tag}.glb`);
    await expect(`CLI ${input.name}`, async () => {
      const runs = [
        ['cli', [], {}],
        ['ours', config, {}],
        ['ours-stock', config, stockEnv],
      ];
      const files = {};
      for (const [tag, extra, vars] of runs) {
        // The config's defaults (auto + context, tangents auto) unless
        // |vars| say else.
        const run = runCli(['draco', input.glb, out(tag), ...extra],
                           {DRACO_UV_PRED: undefined,
                            DRACO_UV_SEAMS: undefined,
                            DRACO_TANGENT_PRED: undefined, ...vars});
        check(run.status === 0, `draco ${tag} exited ${run.status}: ` +
              run.stderr + run.stdout);
        files[tag] = fs.readFileSync(out(tag));
      }
      const marked = hasMarker(parseGlb(files.ours).json);
      check(marked === input.uv, `--config: marker ${marked}`);
      check(!hasMarker(parseGlb(files['ours-stock']).json),
            'DRACO_UV_PRED=draco DRACO_UV_SEAMS=draco ' +
            'DRACO_TANGENT_PRED=draco: marked');
      check(!hasMarker(parseGlb(files.cli).json), 'plain CLI: marked');
      const digests = [];
      for (const tag of ['cli', 'ours', 'ours-stock']) {
        digests.push(JSON.stringify(
            geometryDigests(await ctx.ourIO.readBinary(files[tag]))));
      }
      check(digests[1] === digests[0] && digests[2] === digests[0],
            'CLI outputs differ in triangles');
      if (input.uv) {
        check(files.ours.length < files.cli.length,
              `--config: ${files.ours.length} bytes, the CLI's own ` +
              `${files.cli.length}`);
        let run = runCli(['inspect', out('ours'), ...config]);
        check(run.status === 0,
              `inspect --config: ${run.stderr}${run.stdout}`);
        run = runCli(['inspect', out('ours')]);
        check(run.status !== 0 &&
              /Missing required extension/.test(run.stderr + run.stdout),
              `inspect without --config: exit ${run.status}`);
      }
      ctx.cliSizes.push([input.name, files.cli.length, files.ours.length]);
    });
  }
  await expect('CLI unknown DRACO_UV_PRED', () => {
    const run = runCli(['draco', inputs[0].glb, path.join(work, 'bad.glb'),
                        ...config], {DRACO_UV_PRED: 'bogus'});
    check(run.status !== 0, 'exited 0');
    const output = run.stderr + run.stdout;
    check(/bogus/.test(output) && /weighted_multi/.test(output),
          `message does not name the valid names: ${output}`);
  });
}

function printSizes(inputs, settings, results, cliSizes) {
  console.log('\nGLB bytes (Draco buffer bytes), marker *:');
  console.log(['asset', ...settings.map((s) => s.name)].join('\t'));
  for (const input of inputs) {
    const cells = settings.map((s) => {
      const r = results.get(`${input.name}/${s.name}`);
      return `${r.glb.length} (${r.dracoBytes})${r.marked ? '*' : ''}`;
    });
    console.log([input.name, ...cells].join('\t'));
  }
  console.log('\nCLI gltf-transform draco: plain / --config (auto+context)');
  for (const row of cliSizes) {
    console.log(row.join('\t'));
  }
}

async function main() {
  const ourEncoder = await ourDraco.createEncoderModule({});
  if (typeof ourEncoder.DracoUvModule !== 'function') {
    throw new Error(`${env.packageDir} has no draco-uv encoder API ` +
                    '(DracoUvModule): rebuild the package');
  }
  const npmDecoder = await npmDraco.createDecoderModule({});
  const ctx = {
    npmDecoder,
    ourIO: await registerDracoUv(new NodeIO()),
    npmIO: new NodeIO()
        .registerExtensions([KHRDracoMeshCompression,
                             DracoUvAttributeCompression])
        .registerDependencies({'draco3d.decoder': npmDecoder}),
    plainIO: new NodeIO().registerExtensions([KHRDracoMeshCompression])
        .registerDependencies({'draco3d.decoder': npmDecoder}),
    cliSizes: [],
  };
  const settings = [
    {name: 'stock', uv: false, options: {}},
    {name: 'npm-draco3d', uv: false,
     options: {encoderModule: await npmDraco.createEncoderModule({})}},
    ...UV_SETTINGS.map((s) => ({name: s.name, uv: true,
                                forcesIds: s.forcesIds,
                                neverLarger: s.neverLarger,
                                options: {texCoordCompression:
                                          s.texCoordCompression}})),
  ];
  const inputs = (await makeInputs()).map((input) =>
    ({...input, large: LARGE_ASSETS.includes(input.name)}));
  const results = await encodeAll(inputs, settings);
  await checkOutputs(inputs, settings, results, ctx);
  await checkAutoPaysForTheMarker(inputs, ctx);
  await checkReadBack(inputs, settings, results, ctx);
  await checkNative(inputs, results, ctx);
  await checkCli(inputs, ctx);
  printSizes(inputs, settings, results, ctx.cliSizes);
}

try {
  await main();
} catch (error) {
  fail(error.stack || error.message);
} finally {
  fs.rmSync(work, {recursive: true, force: true});
}
if (failures) {
  console.log(`gltf_transform_test: ${failures} failure(s)`);
  process.exit(1);
}
console.log(`gltf_transform_test: passed (${MARKER})`);
