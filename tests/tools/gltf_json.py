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
"""Questions about the JSON of glTF and GLB files, for the tool tests.

  gltf_json.py has-texcoords FILE        exit 0 if a triangle primitive has
                                         a TEXCOORD_n attribute
  gltf_json.py requires FILE NAME        exit 0 if extensionsRequired has NAME
  gltf_json.py strip FILE NAME OUT       write FILE (.gltf) without NAME in
                                         extensionsUsed/extensionsRequired
  gltf_json.py add FILE NAME OUT         write FILE (.gltf) with NAME added
                                         to extensionsUsed/extensionsRequired
  gltf_json.py same-apart-from FILE_A FILE_B NAME
                                         exit 0 if the two JSONs are equal
                                         once NAME is dropped from the
                                         extension lists and buffer and
                                         buffer view sizes are ignored
"""
import json
import struct
import sys

GLB_MAGIC = 0x46546C67
TRIANGLES = 4


def read_json(path):
    with open(path, 'rb') as f:
        data = f.read()
    if len(data) >= 20 and struct.unpack_from('<I', data, 0)[0] == GLB_MAGIC:
        length = struct.unpack_from('<I', data, 12)[0]
        data = data[20:20 + length]
    return json.loads(data.decode('utf-8'))


def has_texcoords(gltf):
    return any(
        primitive.get('mode', TRIANGLES) == TRIANGLES and
        any(key.startswith('TEXCOORD_') for key in primitive['attributes'])
        for mesh in gltf.get('meshes', []) for primitive in mesh['primitives'])


def without_extension(gltf, name):
    for key in ('extensionsUsed', 'extensionsRequired'):
        if key in gltf:
            gltf[key] = [n for n in gltf[key] if n != name]
            if not gltf[key]:
                del gltf[key]
    return gltf


def with_extension(gltf, name):
    for key in ('extensionsUsed', 'extensionsRequired'):
        gltf[key] = sorted(set(gltf.get(key, [])) | {name})
    return gltf


def without_sizes(gltf):
    for item in gltf.get('buffers', []) + gltf.get('bufferViews', []):
        item.pop('byteLength', None)
        item.pop('byteOffset', None)
    return gltf


def main(argv):
    command, args = argv[1], argv[2:]
    if command == 'has-texcoords':
        return 0 if has_texcoords(read_json(args[0])) else 1
    if command == 'requires':
        return 0 if args[1] in read_json(args[0]).get('extensionsRequired',
                                                      []) else 1
    if command == 'strip':
        with open(args[2], 'w') as f:
            json.dump(without_extension(read_json(args[0]), args[1]), f)
        return 0
    if command == 'add':
        with open(args[2], 'w') as f:
            json.dump(with_extension(read_json(args[0]), args[1]), f)
        return 0
    if command == 'same-apart-from':
        a = without_sizes(without_extension(read_json(args[0]), args[2]))
        b = without_sizes(without_extension(read_json(args[1]), args[2]))
        return 0 if a == b else 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == '__main__':
    sys.exit(main(sys.argv))
