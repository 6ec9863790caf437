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
"""Checks that draco-uv's source folders depend on each other in one direction.

The sources live in two roots: prediction_schemes/<family>/ (the prediction
scheme families) and draco_ext/<capability>/ (everything else). Their
folders form one chain,

  tools -> eval -> gltf -> options -> schemes -> linalg -> common,

where the schemes are every prediction_schemes/ family plus
draco_ext/seams/ (they do not include each other), web -> gltf (the JS
encoder API, whose glTF writes share the glTF encoder's rule for -uv_pred
auto), web -> schemes (the web decoder's Laplacian part on demand: its C
interface and the decoder's import of it), and hooks/ (what Draco's patched sources include) sits above the
schemes and web/ and is included by nothing of ours.

Also: only prediction_schemes/laplacian/ and draco_ext/linalg/ include
Eigen, and options/ includes no Laplacian header but the light
uv_laplacian_settings.h outside an #ifdef DRACO_UV_LAPLACIAN block, so that
a lossless-only build (DRACO_UV_LAPLACIAN=OFF) compiles neither.

Every folder of both roots must be in the table, and every folder of the
table must exist and hold a header.

Usage: layering_test.py SOURCE_ROOT (the repository root, from which the
sources include each other: "draco_ext/...", "prediction_schemes/...")
"""
import pathlib
import re
import sys

ROOTS = ('draco_ext', 'prediction_schemes')

COMMON = 'draco_ext/common'
LINALG = 'draco_ext/linalg'
SEAMS = 'draco_ext/seams'
OPTIONS = 'draco_ext/options'
GLTF = 'draco_ext/gltf'
WEB = 'draco_ext/web'
EVAL = 'draco_ext/eval'

# prediction_schemes/<family>/ and what it may include besides itself. A new
# family is one entry here; the layers above reach it as one of SCHEMES.
SCHEME_FAMILIES = {
    'weighted': {COMMON},
    'laplacian': {COMMON, LINALG},
    'tangent': {COMMON},
}
SCHEMES = {f'prediction_schemes/{name}' for name in SCHEME_FAMILIES} | {SEAMS}

# Each folder and the folders it may include besides itself.
ALLOWED = {
    COMMON: set(),
    LINALG: {COMMON},
    SEAMS: {COMMON},
    **{f'prediction_schemes/{name}': deps
       for name, deps in SCHEME_FAMILIES.items()},
    OPTIONS: {COMMON} | SCHEMES,
    GLTF: {COMMON, OPTIONS},
    WEB: {COMMON, OPTIONS, GLTF} | SCHEMES,
    'draco_ext/hooks': {COMMON, OPTIONS, GLTF, WEB} | SCHEMES,
    EVAL: {COMMON, LINALG, OPTIONS, GLTF} | SCHEMES,
    'draco_ext/tools': {COMMON, OPTIONS, EVAL},
}
EIGEN_FOLDERS = {'prediction_schemes/laplacian', LINALG}
# The only Laplacian header that builds without the Laplacian coder.
LIGHT_LAPLACIAN = 'prediction_schemes/laplacian/uv_laplacian_settings.h'
INCLUDE = re.compile(r'^\s*#\s*include\s+[<"]([^>"]+)[>"]', re.M)


LAPLACIAN_GUARD = re.compile(r'^\s*#\s*(ifdef\s+DRACO_UV_LAPLACIAN\b|if|endif)',
                             re.M)


def inside_laplacian_guard(text, header):
    """Whether every #include of |header| in |text| is inside an
    #ifdef DRACO_UV_LAPLACIAN block (nested #if blocks allowed)."""
    for include in re.finditer(r'^\s*#\s*include\s+[<"]' + re.escape(header),
                               text, re.M):
        stack = []
        for directive in LAPLACIAN_GUARD.finditer(text, 0, include.start()):
            if directive.group(1) == 'endif':
                if stack:
                    stack.pop()
            else:
                stack.append(directive.group(1).startswith('ifdef'))
        if True not in stack:
            return False
    return True


def folder_of(relative):
    """'draco_ext/options/x.h' -> 'draco_ext/options' (None above a folder)."""
    parts = pathlib.PurePosixPath(relative).parts
    return '/'.join(parts[:2]) if len(parts) > 2 else None


def table_cycles():
    """The folders of ALLOWED that reach themselves (the arrows' one way)."""
    def reach(folder, seen):
        for target in ALLOWED.get(folder, ()):
            if target not in seen:
                seen.add(target)
                reach(target, seen)
        return seen
    return [folder for folder in sorted(ALLOWED)
            if folder in reach(folder, set())]


def violations(source_root):
    for folder in table_cycles():
        yield f'layering table: {folder}/ includes itself through others'
    missing = [root for root in ROOTS if not (source_root / root).is_dir()]
    if missing:
        yield f'{source_root}: no {", ".join(missing)} folder (not the root?)'
        return
    for root in ROOTS:
        for entry in sorted((source_root / root).iterdir()):
            name = f'{root}/{entry.name}'
            if entry.is_dir() and name not in ALLOWED:
                yield f'{entry}: folder {name}/ is not in the layering table'
            elif entry.is_file() and entry.suffix in ('.h', '.cc'):
                yield f'{entry}: source outside a folder of {root}/'
    for folder in sorted(ALLOWED):
        if not list((source_root / folder).glob('*.h')):
            yield f'{source_root / folder}: table folder without headers'
    for root in ROOTS:
        for path in sorted((source_root / root).rglob('*')):
            if path.suffix not in ('.h', '.cc'):
                continue
            folder = folder_of(path.relative_to(source_root).as_posix())
            if folder not in ALLOWED:
                continue  # Reported above.
            text = path.read_text(encoding='utf-8')
            for header in INCLUDE.findall(text):
                if header.startswith('Eigen/') and folder not in EIGEN_FOLDERS:
                    yield (f'{path}: includes <{header}> outside '
                           f'{", ".join(sorted(EIGEN_FOLDERS))}')
                if not header.startswith(tuple(r + '/' for r in ROOTS)):
                    continue
                target = folder_of(header)
                if target != folder and target not in ALLOWED[folder]:
                    yield f'{path}: {folder}/ must not include {header}'
                if (folder == OPTIONS and
                        target == 'prediction_schemes/laplacian' and
                        header != LIGHT_LAPLACIAN and
                        not inside_laplacian_guard(text, header)):
                    yield (f'{path}: {OPTIONS}/ may include only '
                           f'{LIGHT_LAPLACIAN}')


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    found = list(violations(pathlib.Path(sys.argv[1])))
    for line in found:
        print('FAIL:', line)
    print(f'layering: {len(found)} violation(s)')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
