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
 * gltf-pipeline (the pinned 4.3.1) through draco3d-uv's gltf-pipeline.js.
 *
 * Each asset of gltf_checks.mjs goes through gltfToGlb (processGlb for the
 * GLB) with dracoOptions: by require('gltf-pipeline') itself (npm draco3d),
 * by the package's wrapper without texCoordCompression (the reference), and
 * with texCoordCompression auto, auto + context seams and weighted_multi.
 * Checked, per asset and setting, reading the GLBs with glTF-Transform and
 * the package's decoder (gltf-transform.mjs):
 *  - the triangles (every attribute) equal the reference's exactly, and the
 *    reference's equal plain gltf-pipeline's;
 *  - DRACOUV_attribute_compression is in extensionsUsed and
 *    extensionsRequired exactly when npm draco3d's decoder fails on some
 *    Draco buffer; never without texCoordCompression (nor in plain
 *    gltf-pipeline's output), never for Box; with weighted_multi and auto +
 *    context always for the large textured assets, whose Draco buffers
 *    every draco-uv coding that marks the file makes smaller than the
 *    reference's, and their files too but for the marker's JSON;
 *  - auto (stock seams) pays for the marker: its GLB is never larger than
 *    the reference's on any asset (Fox among them, which came out 48 bytes
 *    larger when auto compared Draco bytes only), and smaller when marked,
 *    also at compressionLevel 10 and 4, and so is processGltf's glTF
 *    (embedded buffers) of the glTF assets;
 *  - glTF-Transform with npm draco3d's decoder fails on a marked file.
 * Once: processGltf's glTF (embedded buffers) is marked and reads back to the
 * reference's triangles; two concurrent calls with and without
 * texCoordCompression give a marked and an unmarked file; an unknown
 * prediction name rejects with the valid names.
 * Prints the sizes (bytes) per asset and setting.
 *
 *   node tests/web/gltf_pipeline_test.js
 *
 * Environment (tests/web contract): DRACO_UV_WEB_PACKAGE, DRACO_TESTDATA and
 * tests/web/node_modules from tests/web/install-packages.sh.
 */
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');

const DRACO_OPTIONS = {compressionLevel: 7};

async function main(checks) {
  const {ASSETS, LARGE_ASSETS, UV_SETTINGS, check, checkNotLarger,
         checkSmaller, countUndecodable, dracoBytes, geometryDigests,
         hasMarker, parseGlb} = checks;
  const {NodeIO} = await import('@gltf-transform/core');
  const {KHRDracoMeshCompression} = await import('@gltf-transform/extensions');
  const {registerDracoUv, DracoUvAttributeCompression} =
    await import('draco3d-uv/gltf-transform');
  const npmDecoder = await require('draco3d').createDecoderModule({});
  const plainPipeline = require('gltf-pipeline');
  const ours = require('draco3d-uv/gltf-pipeline');
  const ourIO = await registerDracoUv(new NodeIO());
  const npmIO = new NodeIO()
      .registerExtensions(
          [KHRDracoMeshCompression, DracoUvAttributeCompression])
      .registerDependencies({'draco3d.decoder': npmDecoder});

  const settings = [
    {name: 'gltf-pipeline', pipeline: plainPipeline, uv: false},
    {name: 'stock', pipeline: ours, uv: false},
    ...UV_SETTINGS.map((s) => ({name: s.name, pipeline: ours, uv: true,
                                forcesIds: s.forcesIds,
                                neverLarger: s.neverLarger,
                                texCoordCompression: s.texCoordCompression})),
  ];
  const dracoOptions = (s) => ({...DRACO_OPTIONS,
                                texCoordCompression: s.texCoordCompression});

  async function toGlb(pipeline, asset, options) {
    const file = path.join(checks.testdata, asset.file);
    if (file.endsWith('.glb')) {
      return (await pipeline.processGlb(fs.readFileSync(file), options)).glb;
    }
    const gltf = JSON.parse(fs.readFileSync(file, 'utf8'));
    return (await pipeline.gltfToGlb(gltf, {
      resourceDirectory: path.dirname(file), ...options})).glb;
  }

  const rows = [];
  for (const asset of ASSETS) {
    const row = [asset.name];
    let reference = null;
    for (const setting of settings) {
      const what = `${asset.name} ${setting.name}`;
      try {
        const glb = await toGlb(setting.pipeline, asset,
                                {dracoOptions: dracoOptions(setting)});
        const marked = hasMarker(parseGlb(glb).json);
        const {failed, total} = countUndecodable(npmDecoder, glb);
        row.push(`${glb.length} (${dracoBytes(glb)})${marked ? '*' : ''}`);
        check(total > 0, 'no Draco buffers');
        check(marked === (failed > 0),
              `marker ${marked} but npm draco3d fails on ${failed} of ` +
              `${total} Draco buffers`);
        const large = LARGE_ASSETS.includes(asset.name);
        check(marked || !(setting.forcesIds && large),
              'not marked (no primitive used draco-uv)');
        check(!marked || (setting.uv && asset.uv), 'marked');
        const digests = JSON.stringify(
            geometryDigests(await ourIO.readBinary(glb)));
        if (setting.name === 'gltf-pipeline') {
          reference = {digests, glb};
        }
        check(digests === reference.digests,
              'triangles differ from plain gltf-pipeline\'s');
        if (setting.name === 'stock') {
          reference.glb = glb;
        }
        if (setting.uv && large && (marked || !setting.neverLarger)) {
          checkSmaller(glb, reference.glb, marked);
        }
        if (setting.neverLarger) {
          checkNotLarger(glb, reference.glb, marked);
        }
        if (marked) {
          let error = 'did not fail';
          try {
            await npmIO.readBinary(glb);
          } catch (e) {
            error = /Decoding failure/.test(e.message) ? '' : e.message;
          }
          check(!error, `glTF-Transform with npm draco3d: ${error}`);
        }
      } catch (error) {
        checks.fail(`${what}: ${error.message}`);
      }
    }
    rows.push(row);
  }

  // auto pays for the marker under other compression levels, and in
  // processGltf's glTF with embedded buffers.
  const auto = {prediction: 'auto'};
  let markedAuto = 0;
  for (const asset of ASSETS) {
    for (const compressionLevel of [10, 4]) {
      try {
        const [stock, withAuto] = [
          await toGlb(ours, asset, {dracoOptions: {compressionLevel}}),
          await toGlb(ours, asset, {dracoOptions: {
            compressionLevel, texCoordCompression: auto}}),
        ];
        const marked = hasMarker(parseGlb(withAuto).json);
        markedAuto += marked ? 1 : 0;
        checkNotLarger(withAuto, stock, marked);
      } catch (error) {
        checks.fail(`${asset.name} auto -cl ${compressionLevel}: ` +
                    error.message);
      }
    }
    if (!asset.file.endsWith('.gltf')) {
      continue;
    }
    try {
      const file = path.join(checks.testdata, asset.file);
      const written = async (dracoOptions) => JSON.stringify((
        await ours.processGltf(JSON.parse(fs.readFileSync(file, 'utf8')), {
          resourceDirectory: path.dirname(file), dracoOptions})).gltf);
      const stock = await written(DRACO_OPTIONS);
      const withAuto = await written({...DRACO_OPTIONS,
                                      texCoordCompression: auto});
      checkNotLarger(withAuto, stock, hasMarker(JSON.parse(withAuto)));
    } catch (error) {
      checks.fail(`${asset.name} auto processGltf: ${error.message}`);
    }
  }
  if (markedAuto === 0) {
    checks.fail('auto at -cl 10 and 4: no file was marked');
  }

  // processGltf: a glTF with embedded buffers.
  const lantern = ASSETS.find((a) => a.name === 'Lantern');
  const lanternFile = path.join(checks.testdata, lantern.file);
  const lanternGltf = () => JSON.parse(fs.readFileSync(lanternFile, 'utf8'));
  try {
    const setting = settings.find((s) => s.name === 'auto+context');
    const {gltf} = await ours.processGltf(lanternGltf(), {
      resourceDirectory: path.dirname(lanternFile),
      dracoOptions: dracoOptions(setting)});
    check(hasMarker(gltf), 'processGltf: not marked');
    const out = path.join(checks.work, 'lantern.gltf');
    fs.writeFileSync(out, JSON.stringify(gltf));
    const stockGlb = await toGlb(ours, lantern, {dracoOptions: DRACO_OPTIONS});
    check(JSON.stringify(geometryDigests(await ourIO.read(out))) ===
          JSON.stringify(geometryDigests(await ourIO.readBinary(stockGlb))),
          'processGltf: triangles differ from stock coding\'s');
  } catch (error) {
    checks.fail(`processGltf: ${error.message}`);
  }

  // Concurrent calls keep their own texture coordinate settings.
  try {
    const [withUv, without] = await Promise.all([
      toGlb(ours, lantern, {dracoOptions: {
        ...DRACO_OPTIONS, texCoordCompression: {prediction: 'auto'}}}),
      toGlb(ours, lantern, {dracoOptions: DRACO_OPTIONS}),
    ]);
    check(hasMarker(parseGlb(withUv).json) &&
          !hasMarker(parseGlb(without).json),
          'concurrent calls: markers mixed up');
    check(countUndecodable(npmDecoder, without).failed === 0,
          'concurrent calls: the call without options used draco-uv ids');
  } catch (error) {
    checks.fail(`concurrent calls: ${error.message}`);
  }

  // Unknown names are errors naming the valid ones.
  try {
    await toGlb(ours, lantern, {dracoOptions: {
      texCoordCompression: {prediction: 'bogus'}}});
    checks.fail('unknown prediction name: no error');
  } catch (error) {
    if (!/bogus/.test(error.message) ||
        !/weighted_multi/.test(error.message)) {
      checks.fail(`unknown prediction name: "${error.message}"`);
    }
  }

  console.log('\nGLB bytes (Draco buffer bytes), marker *:');
  console.log(['asset', ...settings.map((s) => s.name)].join('\t'));
  for (const row of rows) {
    console.log(row.join('\t'));
  }
}

(async () => {
  const checks = {...await import('./gltf_checks.mjs')};
  const env = checks.environment(__dirname);
  let failures = 0;
  checks.fail = (message) => {
    console.log(`FAIL: ${message}`);
    failures++;
  };
  checks.testdata = env.testdata;
  checks.work = fs.mkdtempSync(path.join(os.tmpdir(), 'gltf-pipeline-test-'));
  try {
    const encoder = await require('draco3d-uv').createEncoderModule({});
    if (typeof encoder.DracoUvModule !== 'function') {
      throw new Error(`${env.packageDir} has no draco-uv encoder API ` +
                      '(DracoUvModule): rebuild the package');
    }
    await main(checks);
  } catch (error) {
    checks.fail(error.stack || error.message);
  } finally {
    fs.rmSync(checks.work, {recursive: true, force: true});
  }
  if (failures) {
    console.log(`gltf_pipeline_test: ${failures} failure(s)`);
    process.exit(1);
  }
  console.log('gltf_pipeline_test: passed');
})();
