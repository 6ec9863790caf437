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
 * Tangent prediction through the package's glTF writers (CTest
 * web.tangent_pipelines; the web test contract, tests/web/CMakeLists.txt):
 * glTF-Transform's draco() with registerDracoUv({tangentCompression}) and
 * the CLI config (gltf-transform.config.mjs, DRACO_TANGENT_PRED), and
 * gltf-pipeline through draco3d-uv/gltf-pipeline
 * (dracoOptions.tangentCompression), on testdata/*_tangents.glb (TANGENT,
 * which both pipelines hand the encoder as GENERIC). Per asset, writer and
 * -tangent_pred name (mikktspace, geometric, auto; stock coding is the
 * reference, for gltf-pipeline with the tangents quantized by
 * quantizationBits 8, which the tangent names default to, as gltf-pipeline
 * itself leaves TANGENT unquantized):
 *  - the file reads back through the package's decoder to the stock-coded
 *    file's triangles exactly, TANGENT included (same quantisation; the
 *    prediction is lossless);
 *  - DRACOUV_attribute_compression is in extensionsUsed and
 *    extensionsRequired exactly when npm draco3d 1.5.9's decoder fails on
 *    some Draco buffer of the file, with an error; the named schemes always
 *    mark the file (these meshes meet every condition of the prediction);
 *    auto's file is never larger than stock coding's, and smaller when
 *    marked;
 *  - the named schemes make crane_spot's Draco buffer smaller;
 *  - glTF-Transform refuses a marked file with npm draco3d's decoder
 *    ("Decoding failure");
 *  - an unknown tangentCompression.prediction is rejected, naming the
 *    valid names.
 * The CLI: `gltf-transform draco` with the config writes crane_spot with
 * tangent prediction by default (a smaller Draco buffer than with
 * DRACO_TANGENT_PRED=draco, the same triangles), and an unknown
 * DRACO_TANGENT_PRED fails naming the valid names.
 * Prints the sizes (bytes) per asset and setting.
 *
 *   node tests/web/tangent_pipelines_test.mjs
 *
 * Environment (tests/web contract): DRACO_UV_WEB_PACKAGE, DRACO_TESTDATA,
 * DRACO_UV_SOURCE_DIR (default: two folders up), and tests/web/node_modules
 * from tests/web/install-packages.sh. Exit 0 pass, 1 fail, 77 skip.
 */
'use strict';

import {spawnSync} from 'node:child_process';
import fs from 'node:fs';
import {createRequire} from 'node:module';
import os from 'node:os';
import path from 'node:path';
import {fileURLToPath} from 'node:url';
import {check, countUndecodable, dracoBuffers, environment, geometryDigests,
        hasMarker, parseGlb} from './gltf_checks.mjs';

const kHere = path.dirname(fileURLToPath(import.meta.url));
environment(kHere);
const kSource = process.env.DRACO_UV_SOURCE_DIR || path.resolve(kHere, '../..');
const kAssets = ['small_torus_uv', 'small_cube_sphere', 'crane_spot'];
// The -tangent_pred names written; 'draco' (stock coding) is the reference.
const kNames = ['mikktspace', 'geometric', 'auto'];

const require = createRequire(import.meta.url);
const {NodeIO} = await import('@gltf-transform/core');
const {KHRDracoMeshCompression} = await import('@gltf-transform/extensions');
const {draco} = await import('@gltf-transform/functions');
const {default: npmDraco} = await import('draco3d');
const {registerDracoUv, DracoUvAttributeCompression} =
  await import('draco3d-uv/gltf-transform');
const pipeline = require('draco3d-uv/gltf-pipeline');

const work = fs.mkdtempSync(path.join(os.tmpdir(), 'tangent-pipelines-'));
let failures = 0;

/** Runs check |fn|; a thrown Error is one failure. */
async function expect(what, fn) {
  try {
    await fn();
  } catch (error) {
    console.log(`FAIL: ${what}: ${error.message}`);
    failures++;
  }
}

async function rejectsWith(fn, pattern) {
  try {
    await fn();
  } catch (error) {
    return pattern.test(error.message) ? '' :
      `failed with "${error.message}", expected ${pattern}`;
  }
  return 'did not fail';
}

const sum = (buffers) => buffers.reduce((total, b) => total + b.length, 0);

/** glTF-Transform's draco() with the package, tangents coded by |name|. */
async function writeWithGltfTransform(input, name) {
  const io = await registerDracoUv(
      new NodeIO(), name === 'draco' ? {} :
        {tangentCompression: {prediction: name}});
  const document = await io.read(input);
  await document.transform(draco());
  return io.writeBinary(document);
}

/**
 * gltf-pipeline's processGlb with the package, tangents coded by |name|.
 * gltf-pipeline leaves TANGENT unquantized (its quantization bits are per
 * POSITION, NORMAL, TEXCOORD, COLOR and GENERIC by semantic name), and
 * tangentCompression quantizes tangents with 8 bits where nothing else does
 * (draco_transcoder's -qtg default): the reference is stock prediction with
 * the tangents quantized so, by -qtg 8 ('draco' with quantizationBits 8).
 */
async function writeWithGltfPipeline(input, name) {
  const dracoOptions = {compressionLevel: 7};
  dracoOptions.tangentCompression = name === 'draco' ?
      {prediction: 'draco', quantizationBits: 8} : {prediction: name};
  const {glb} = await pipeline.processGlb(fs.readFileSync(input),
                                          {dracoOptions});
  return new Uint8Array(glb.buffer, glb.byteOffset, glb.byteLength);
}

/** The triangles of a GLB read with the package's decoder. */
async function readBack(readIo, glb) {
  return geometryDigests(await readIo.readBinary(glb));
}

async function checkWriter(writer, write, readIo, npmDecoder) {
  for (const asset of kAssets) {
    const input = path.join(kSource, 'testdata', `${asset}_tangents.glb`);
    const reference = await write(input, 'draco');
    const referenceDigests = await readBack(readIo, reference);
    const referenceDraco = sum(dracoBuffers(reference));
    await expect(`${writer} ${asset} stock`, () => {
      check(!hasMarker(parseGlb(reference).json), 'stock coding marked');
      check(referenceDigests.some((d) => d.includes('TANGENT')),
            'no TANGENT read back');
    });
    const sizes = [`stock ${reference.length} (Draco ${referenceDraco})`];
    for (const name of kNames) {
      const glb = await write(input, name);
      fs.writeFileSync(path.join(work, `${asset}.${writer}.${name}.glb`), glb);
      const dracoBytes = sum(dracoBuffers(glb));
      const marked = hasMarker(parseGlb(glb).json);
      sizes.push(`${name} ${glb.length} (Draco ${dracoBytes})` +
                 (marked ? ' marked' : ''));
      await expect(`${writer} ${asset} ${name}`, async () => {
        const digests = await readBack(readIo, glb);
        check(JSON.stringify(digests) === JSON.stringify(referenceDigests),
              `reads back to other triangles than stock coding's:\n  ` +
              `${digests}\n  ${referenceDigests}`);
        const {failed, total} = countUndecodable(npmDecoder, glb);
        check(marked === (failed > 0),
              `marker ${marked} but npm draco3d fails on ${failed} of ` +
              `${total} Draco buffers`);
        if (name === 'auto') {
          check(marked ? glb.length < reference.length :
                         glb.length <= reference.length,
                `auto: ${glb.length} bytes, stock coding's ` +
                `${reference.length}`);
        } else {
          check(marked, 'not marked with a named tangent prediction');
          if (asset === 'crane_spot') {
            check(dracoBytes < referenceDraco,
                  `Draco buffer ${dracoBytes} bytes, stock's ` +
                  `${referenceDraco}`);
          }
        }
        if (marked && writer === 'gltf-transform') {
          const stockIo = new NodeIO()
              .registerExtensions([KHRDracoMeshCompression,
                                   DracoUvAttributeCompression])
              .registerDependencies({
                'draco3d.decoder': await npmDraco.createDecoderModule()});
          const problem = await rejectsWith(() => stockIo.readBinary(glb),
                                            /Decoding failure/);
          check(!problem, `with npm draco3d's decoder: ${problem}`);
        }
      });
    }
    console.log(`${writer} ${asset}: ${sizes.join(', ')}`);
  }
}

/** The gltf-transform CLI with the package's config on crane_spot. */
async function checkCli(readIo) {
  const cli = path.join(kHere, 'node_modules', '.bin', 'gltf-transform');
  const config = path.join(kHere, 'node_modules', 'draco3d-uv',
                           'gltf-transform.config.mjs');
  const input = path.join(kSource, 'testdata', 'crane_spot_tangents.glb');
  const run = (out, environment) => spawnSync(
      cli, ['draco', input, out, '--config', config],
      {env: {...process.env, ...environment}, encoding: 'utf8'});
  const outputs = {};
  for (const [name, environment] of [['default', {}],
                                     ['draco', {DRACO_TANGENT_PRED: 'draco'}]]) {
    const out = path.join(work, `crane_spot.cli.${name}.glb`);
    const result = run(out, environment);
    await expect(`CLI ${name}`, () => check(result.status === 0,
                                            result.stderr || result.stdout));
    if (result.status === 0) outputs[name] = fs.readFileSync(out);
  }
  if (outputs.default && outputs.draco) {
    await expect('CLI default tangent prediction', async () => {
      const [a, b] = [outputs.default, outputs.draco].map(
          (glb) => sum(dracoBuffers(glb)));
      console.log(`CLI crane_spot: default Draco ${a} bytes, ` +
                  `DRACO_TANGENT_PRED=draco ${b}`);
      check(a < b, 'the default (auto) is not smaller than stock tangents');
      check(JSON.stringify(await readBack(readIo, outputs.default)) ===
            JSON.stringify(await readBack(readIo, outputs.draco)),
            'other triangles than with stock tangents');
    });
  }
  const bad = run(path.join(work, 'bad.glb'), {DRACO_TANGENT_PRED: 'mikkt'});
  await expect('CLI unknown DRACO_TANGENT_PRED', () => check(
      bad.status !== 0 && /mikktspace/.test(bad.stderr + bad.stdout),
      `status ${bad.status}: ${bad.stderr}`));
}

async function main() {
  const readIo = await registerDracoUv(new NodeIO());
  const npmDecoder = await npmDraco.createDecoderModule({});
  try {
    await checkWriter('gltf-transform', writeWithGltfTransform, readIo,
                      npmDecoder);
    await checkWriter('gltf-pipeline', writeWithGltfPipeline, readIo,
                      npmDecoder);
    await expect('unknown tangentCompression.prediction', async () => {
      const problem = await rejectsWith(
          () => registerDracoUv(new NodeIO(),
                                {tangentCompression: {prediction: 'mikkt'}}),
          /tangentCompression\.prediction: .*mikktspace/);
      check(!problem, problem);
    });
    await checkCli(readIo);
  } finally {
    fs.rmSync(work, {recursive: true, force: true});
  }
  console.log(`tangent_pipelines_test: ${failures} failures`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(`FAIL: ${error.stack || error}`);
  process.exit(1);
});
