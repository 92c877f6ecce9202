// Whole-file sizes, gzip'd: `hullpack pack` (render meshes + collision hulls) against the same meshes
// compressed by Draco through glTF-Transform (edgebreaker, speed 0, the bits hullpack chose) without
// hulls. Draco gets the meshes as hullpack's --fallback file holds them (pruned, decoded), so both
// sides code the same vertices, triangles and attributes.
//
//   node tools/bench/size_vs_draco.mjs build/tools/hullpack/hullpack INPUT... [--max-error F]
//
// Prints one line per input and the median and geometric mean of packed/draco. Each line splits the
// packed file: render (the gzip'd file packed with --hulls none), hulls (what the hulls add to the
// gzip'd file), hull_json and hull_bin (what they add to the JSON and binary chunks, not gzip'd),
// the hull and point counts, and concavity: the largest of the meshes' hull concavity (pack's
// report: the larger one-sided Hausdorff distance between surface and hulls, fraction of the
// diagonal; the hull points' quantization error comes on top). Options after INPUT... are passed to `hullpack pack` (e.g.
// --max-error F, --hull-error F, --max-concavity D). npm dev
// dependencies: @gltf-transform/core, @gltf-transform/extensions, @gltf-transform/functions,
// draco3dgltf.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { gzipSync } from 'node:zlib';

import { Logger, NodeIO } from '@gltf-transform/core';
import { KHRDracoMeshCompression } from '@gltf-transform/extensions';
import { draco } from '@gltf-transform/functions';
import draco3d from 'draco3dgltf';

const args = process.argv.slice(2);
if (args.length < 2 || args.includes('--help')) {
  console.error('usage: node size_vs_draco.mjs HULLPACK INPUT... [PACK OPTION...]');
  process.exit(args.includes('--help') ? 0 : 64);
}
const hullpack = args[0];
// pack options that take no value
const PACK_FLAGS = new Set(['--fallback', '--quantized-hulls', '--keep-order', '--fast-decode', '--ascii', '--skinned-hulls']);
const extra = [];
const inputs = [];
for (let i = 1; i < args.length; ++i) {
  if (!args[i].startsWith('--')) inputs.push(args[i]);
  else if (args[i].includes('=') || PACK_FLAGS.has(args[i])) extra.push(args[i]);
  else extra.push(args[i], args[++i]);
}

// (the fallback file's HULLPACK_mesh_compression is optional and unknown to glTF-Transform)
const io = new NodeIO().setLogger(new Logger(Logger.Verbosity.ERROR)).registerExtensions([KHRDracoMeshCompression]).registerDependencies({
  'draco3d.encoder': await draco3d.createEncoderModule(),
  'draco3d.decoder': await draco3d.createDecoderModule(),
});
const gz = (bytes) => gzipSync(bytes, { level: 9 }).length;
// [JSON chunk bytes, BIN chunk bytes, hulls, points] of a GLB (hulls: POINTS meshes).
function chunks(glb) {
  const jsonLength = glb.readUInt32LE(12);
  const json = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  const binLength = glb.length > 20 + jsonLength ? glb.readUInt32LE(20 + jsonLength) : 0;
  let hulls = 0;
  let points = 0;
  for (const mesh of json.meshes ?? []) {
    const prim = mesh.primitives[0];
    if (prim.mode !== 0) continue;
    ++hulls;
    points += json.accessors[prim.attributes.POSITION].count;
  }
  return [jsonLength, binLength, hulls, points];
}
const tmp = mkdtempSync(path.join(tmpdir(), 'size_vs_draco-'));
const ratios = [];
const concavities = [];
let hullTotal = 0;
try {
  console.log(
    'file,packed_gzip,draco_gzip,ratio,render_gzip,hulls_gzip,hull_json,hull_bin,hulls,points,concavity',
  );
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
    const renderOnly = path.join(tmp, 'render.glb');
    run(['-o', renderOnly, '--hulls', 'none']);
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
    const withGlb = readFileSync(withHulls);
    const renderGlb = readFileSync(renderOnly);
    const [jw, bw, hulls, points] = chunks(withGlb);
    const [jr, br] = chunks(renderGlb);
    const render = gz(renderGlb);
    const concavity = Math.max(...meshes.map((m) => m.hull_error?.concavity ?? 0));
    concavities.push(concavity);
    hullTotal += hulls;
    console.log(
      [
        path.basename(input),
        packed,
        dracoSize,
        (packed / dracoSize).toFixed(3),
        render,
        packed - render,
        jw - jr,
        bw - br,
        hulls,
        points,
        concavity.toFixed(4),
      ].join(','),
    );
  }
} finally {
  rmSync(tmp, { recursive: true, force: true });
}
function medianOf(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}
const geomean = Math.exp(ratios.reduce((s, r) => s + Math.log(r), 0) / ratios.length);
console.log(
  `median ${medianOf(ratios).toFixed(3)} geomean ${geomean.toFixed(3)} over ${ratios.length} files; ` +
    `${hullTotal} hulls, median concavity ${medianOf(concavities).toFixed(4)}, ` +
    `largest ${Math.max(...concavities).toFixed(4)}`,
);
