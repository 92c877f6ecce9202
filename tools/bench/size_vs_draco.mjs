// Whole-file sizes, gzip'd: `hullpack pack` (render meshes + collision hulls) against the same meshes
// compressed by Draco through glTF-Transform (edgebreaker, speed 0, the bits hullpack chose) without
// hulls. Draco gets the meshes as hullpack's --fallback file holds them (pruned, decoded), so both
// sides code the same vertices, triangles and attributes.
//
//   node tools/bench/size_vs_draco.mjs build/tools/hullpack/hullpack INPUT... [--max-error F]
//
// Prints one line per input and the median and geometric mean of packed/draco. npm dev
// dependencies: @gltf-transform/core, @gltf-transform/extensions, @gltf-transform/functions,
// draco3dgltf.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { gzipSync } from 'node:zlib';

import { NodeIO } from '@gltf-transform/core';
import { KHRDracoMeshCompression } from '@gltf-transform/extensions';
import { draco } from '@gltf-transform/functions';
import draco3d from 'draco3dgltf';

const args = process.argv.slice(2);
if (args.length < 2 || args.includes('--help')) {
  console.error('usage: node size_vs_draco.mjs HULLPACK INPUT... [--max-error F]');
  process.exit(args.includes('--help') ? 0 : 64);
}
const hullpack = args[0];
const extra = [];
const inputs = [];
for (let i = 1; i < args.length; ++i) {
  if (args[i] === '--max-error') extra.push('--max-error', args[++i]);
  else inputs.push(args[i]);
}

const io = new NodeIO().registerExtensions([KHRDracoMeshCompression]).registerDependencies({
  'draco3d.encoder': await draco3d.createEncoderModule(),
  'draco3d.decoder': await draco3d.createDecoderModule(),
});
const gz = (bytes) => gzipSync(bytes, { level: 9 }).length;
const tmp = mkdtempSync(path.join(tmpdir(), 'size_vs_draco-'));
const ratios = [];
try {
  console.log('file,packed_gzip,draco_gzip,ratio');
  for (const input of inputs) {
    const withHulls = path.join(tmp, 'with.glb');
    const plain = path.join(tmp, 'plain.glb');
    const report = path.join(tmp, 'report.json');
    const run = (more) =>
      execFileSync(hullpack, ['pack', input, '--force', '--quiet', ...extra, ...more], {
        stdio: ['ignore', 'ignore', 'inherit'],
      });
    run(['-o', withHulls, '--report', report]);
    run(['-o', plain, '--hulls', 'none', '--fallback']);
    const meshes = JSON.parse(readFileSync(report, 'utf8')).meshes;
    const bits = Math.max(...meshes.map((m) => m.position_bits));
    const doc = await io.read(plain);
    for (const ext of doc.getRoot().listExtensionsUsed()) ext.dispose();
    doc.createExtension(KHRDracoMeshCompression).setRequired(true);
    await doc.transform(
      draco({
        method: 'edgebreaker',
        encodeSpeed: 0,
        decodeSpeed: 0,
        quantizePosition: bits,
        quantizeNormal: 10,
        quantizeTexcoord: 12,
        quantizeColor: 10,
        quantizeGeneric: 10,
      }),
    );
    const dracoBytes = await io.writeBinary(doc);
    const packed = gz(readFileSync(withHulls));
    const dracoSize = gz(dracoBytes);
    ratios.push(packed / dracoSize);
    console.log(`${path.basename(input)},${packed},${dracoSize},${(packed / dracoSize).toFixed(3)}`);
  }
} finally {
  rmSync(tmp, { recursive: true, force: true });
}
const sorted = [...ratios].sort((a, b) => a - b);
const mid = sorted.length >> 1;
const median = sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
const geomean = Math.exp(ratios.reduce((s, r) => s + Math.log(r), 0) / ratios.length);
console.log(`median ${median.toFixed(3)} geomean ${geomean.toFixed(3)} over ${ratios.length} files`);
