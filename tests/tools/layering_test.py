#!/usr/bin/env python3
# Copyright 2026 The draco-uv Authors.
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#      http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.
"""Checks that draco_ext/'s folders depend on each other in one direction.

  tools -> eval -> gltf -> options -> schemes (weighted, laplacian, seams)
  -> linalg -> common, and web -> gltf (the JS encoder API, whose glTF
  writes share the glTF encoder's rule for -uv_pred auto), with hooks/
  (what Draco's patched sources include) above the schemes and web/ and
  below nothing of ours.

Also: only laplacian/ and linalg/ include Eigen, and options/ includes no
Laplacian header but the light uv_laplacian_settings.h, so that a
lossless-only build (DRACO_UV_LAPLACIAN=OFF) compiles neither.

Usage: layering_test.py DRACO_EXT_DIR
"""
import pathlib
import re
import sys

ALLOWED = {
    'common': set(),
    'linalg': {'common'},
    'weighted': {'common'},
    'seams': {'common'},
    'laplacian': {'common', 'linalg'},
    'options': {'common', 'weighted', 'seams', 'laplacian'},
    'gltf': {'common', 'options'},
    'web': {'common', 'options', 'gltf'},
    'hooks': {'common', 'weighted', 'seams', 'laplacian', 'options', 'gltf',
              'web'},
    'eval': {'common', 'weighted', 'seams', 'laplacian', 'linalg', 'options',
             'gltf'},
    'tools': {'common', 'options', 'eval'},
}
EIGEN_FOLDERS = {'laplacian', 'linalg'}
# The only Laplacian header that builds without the Laplacian coder.
LIGHT_LAPLACIAN = 'draco_ext/laplacian/uv_laplacian_settings.h'
INCLUDE = re.compile(r'^\s*#\s*include\s+[<"]([^>"]+)[>"]', re.M)


def violations(root):
    for path in sorted(root.rglob('*')):
        if path.suffix not in ('.h', '.cc'):
            continue
        folder = path.relative_to(root).parts[0]
        if folder not in ALLOWED:
            yield f'{path}: folder {folder}/ is not in the layering table'
            continue
        for header in INCLUDE.findall(path.read_text(encoding='utf-8')):
            if header.startswith('Eigen/') and folder not in EIGEN_FOLDERS:
                yield f'{path}: includes <{header}> outside laplacian/, linalg/'
            if not header.startswith('draco_ext/'):
                continue
            target = header.split('/')[1]
            if target != folder and target not in ALLOWED[folder]:
                yield f'{path}: {folder}/ must not include {header}'
            if (folder == 'options' and target == 'laplacian' and
                    header != LIGHT_LAPLACIAN):
                yield f'{path}: options/ may include only {LIGHT_LAPLACIAN}'


def main():
    root = pathlib.Path(sys.argv[1])
    found = list(violations(root))
    for line in found:
        print('FAIL:', line)
    if not list(root.rglob('*.h')):
        print('FAIL: no headers under', root)
        return 1
    print(f'layering: {len(found)} violation(s)')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
