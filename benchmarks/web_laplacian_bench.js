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
//
// Decode times of .drc files in Node.js with several WebAssembly decoders
// (benchmarks/web.md, "The Laplacian part on demand"): each decoder is a
// draco_wasm_wrapper.js with its draco_decoder.wasm beside it (and, for the
// decoder with the Laplacian part on demand, draco_decoder_laplacian.wasm).
// Per file it times the first decode of a fresh module (for the on-demand
// decoder: reading, compiling and running the part), then ROUNDS decodes
// interleaved across the decoders, and prints a Markdown table of the first
// decode, the minimum and the median in milliseconds of the process's CPU
// time (user + system: the decode runs on one thread, and preemption on a
// busy machine does not inflate it).
//
//   node benchmarks/web_laplacian_bench.js [--rounds N] NAME=WRAPPER.js ...
//       -- FILE.drc ...
'use strict';

const fs = require('fs');
const path = require('path');

async function loadModule(wrapper) {
  const factory = require(path.resolve(wrapper));
  const wasmBinary =
      fs.readFileSync(path.join(path.dirname(wrapper), 'draco_decoder.wasm'));
  return factory({wasmBinary});
}

function cpuMs() {
  const {user, system} = process.cpuUsage();
  return (user + system) / 1000;
}

// Decodes |bytes| as three.js does up to the geometry (without copying the
// attributes out); returns CPU milliseconds.
function timeDecode(module, bytes) {
  const start = cpuMs();
  const decoder = new module.Decoder();
  const mesh = new module.Mesh();
  const status = decoder.DecodeArrayToMesh(bytes, bytes.byteLength, mesh);
  const ms = cpuMs() - start;
  if (!status.ok()) throw new Error(status.error_msg());
  module.destroy(mesh);
  module.destroy(decoder);
  return ms;
}

function median(values) {
  const sorted = values.slice().sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

async function main() {
  const args = process.argv.slice(2);
  let rounds = 10;
  if (args[0] === '--rounds') {
    rounds = Number(args[1]);
    args.splice(0, 2);
  }
  const split = args.indexOf('--');
  if (split < 1 || split === args.length - 1) {
    throw new Error('usage: web_laplacian_bench.js [--rounds N] ' +
                    'NAME=WRAPPER.js ... -- FILE.drc ...');
  }
  const decoders = args.slice(0, split).map((arg) => {
    const [name, wrapper] = arg.split('=');
    return {name, wrapper};
  });
  const files = args.slice(split + 1);
  const rows = [];
  for (const file of files) {
    const bytes = new Int8Array(fs.readFileSync(file));
    const times = decoders.map(() => []);
    const first = [];
    for (const decoder of decoders) {
      const module = await loadModule(decoder.wrapper);
      first.push(timeDecode(module, bytes));
      decoder.module = module;
    }
    for (let round = 0; round < rounds; ++round) {
      decoders.forEach((decoder, i) => {
        times[i].push(timeDecode(decoder.module, bytes));
      });
    }
    decoders.forEach((decoder, i) => {
      rows.push([path.basename(file), decoder.name, first[i].toFixed(1),
                 Math.min(...times[i]).toFixed(1),
                 median(times[i]).toFixed(1)]);
    });
  }
  console.log('| file | decoder | first decode | min | median |');
  console.log('| --- | --- | ---: | ---: | ---: |');
  for (const row of rows) console.log(`| ${row.join(' | ')} |`);
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
