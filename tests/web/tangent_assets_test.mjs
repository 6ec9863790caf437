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
 * testdata/*_tangents.glb with the pinned npm packages (CTest
 * web.tangent_assets; the web test contract, tests/web/CMakeLists.txt):
 *  - scripts/make-tangent-assets.mjs --obj makes each of them again from
 *    its OBJ byte for byte (so a change of the pinned glTF-Transform or
 *    mikktspace that changes them is noticed);
 *  - scripts/check-tangent-assets.mjs's checks pass on each: glTF-Validator
 *    without errors, unit tangents with w = +-1, and the tangents recomputed
 *    from the file the same.
 *
 *   node tests/web/tangent_assets_test.mjs
 *
 * Needs only tests/web/node_modules. Exit 0 pass, 1 fail.
 */

import fs from 'node:fs';
import path from 'node:path';
import {fileURLToPath} from 'node:url';

import {checkGlb} from '../../scripts/check-tangent-assets.mjs';
import {kRepo, loadPackages, objToTangentGlb} from '../../scripts/make-tangent-assets.mjs';

const kAssets = ['small_torus_uv', 'small_cube_sphere', 'crane_spot'];

const here = path.dirname(fileURLToPath(import.meta.url));
if (path.resolve(here, '../..') !== kRepo) throw new Error('unexpected layout');

const pkgs = loadPackages();
let failed = 0;
for (const name of kAssets) {
  const obj = path.join(kRepo, 'testdata', `${name}.obj`);
  const glbFile = path.join(kRepo, 'testdata', `${name}_tangents.glb`);
  const {glb} = await objToTangentGlb(pkgs, fs.readFileSync(obj, 'utf8'), `${name}_tangents`, obj);
  const same = Buffer.compare(Buffer.from(glb), fs.readFileSync(glbFile)) === 0;
  const {line, ok} = await checkGlb(pkgs, glbFile, true);
  console.log(`${line}\n  remade from ${name}.obj: ${same ? 'same bytes' : 'DIFFERENT bytes'}`);
  if (!same || !ok) failed++;
}
console.log(failed ? `FAIL: ${failed} of ${kAssets.length} assets` : 'PASS');
process.exit(failed ? 1 : 0);
