// make_morph_glb.mjs: writes a small glTF (GLB) with morph targets for the engine test, generated
// in code: a UV sphere of radius 1 with two named blend shapes ("inflate": every vertex 0.25 out
// along its normal, with no normal offsets; "squash": y halved, x and z widened, with normal
// offsets), default weights [0, 0] and a clip "breathe" that drives both weights (LINEAR keys at
// 0, 1 and 2 s: [0, 0], [1, 0.5], [0, 0]).
//
//   node tests/web/make_morph_glb.mjs --out WORK/morph.glb
import fs from 'node:fs';
import { glbBytes } from './glb_container.mjs';

const a = {};
for (let i = 2; i + 1 < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
if (!a.out) {
  console.error('usage: make_morph_glb.mjs --out FILE.glb');
  process.exit(64);
}

const SEGMENTS = 32;
const RINGS = 16;
const positions = [];
const normals = [];
const inflate = [];
const squash = [];
const squashNormals = [];
for (let r = 0; r <= RINGS; ++r) {
  const theta = (Math.PI * r) / RINGS;
  for (let s = 0; s <= SEGMENTS; ++s) {
    const phi = (2 * Math.PI * s) / SEGMENTS;
    const n = [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)];
    positions.push(...n);
    normals.push(...n);
    inflate.push(0.25 * n[0], 0.25 * n[1], 0.25 * n[2]);
    squash.push(0.25 * n[0], -0.5 * n[1], 0.25 * n[2]);
    // The squashed sphere's normal, unnormalized offsets from the round one's.
    const m = [n[0] / 1.25, n[1] / 0.5, n[2] / 1.25];
    const len = Math.hypot(...m);
    squashNormals.push(m[0] / len - n[0], m[1] / len - n[1], m[2] / len - n[2]);
  }
}
const indices = [];
for (let r = 0; r < RINGS; ++r) {
  for (let s = 0; s < SEGMENTS; ++s) {
    const i = r * (SEGMENTS + 1) + s;
    const j = i + SEGMENTS + 1;
    if (r > 0) indices.push(i, i + 1, j);
    if (r < RINGS - 1) indices.push(i + 1, j + 1, j);
  }
}

const chunks = [];
const bufferViews = [];
const accessors = [];
let length = 0;
function add(array, type, componentType, extra = {}) {
  const bytes = Buffer.from(array.buffer, array.byteOffset, array.byteLength);
  const padded = Buffer.concat([bytes, Buffer.alloc((4 - (bytes.length % 4)) % 4)]);
  bufferViews.push({ buffer: 0, byteOffset: length, byteLength: bytes.length });
  chunks.push(padded);
  length += padded.length;
  const width = { SCALAR: 1, VEC3: 3 }[type];
  accessors.push({ bufferView: bufferViews.length - 1, componentType, count: array.length / width, type, ...extra });
  return accessors.length - 1;
}
function bounds(values) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  values.forEach((v, i) => {
    min[i % 3] = Math.min(min[i % 3], Math.fround(v));
    max[i % 3] = Math.max(max[i % 3], Math.fround(v));
  });
  return { min, max };
}
const F = 5126;
const position = add(new Float32Array(positions), 'VEC3', F, bounds(positions));
const normal = add(new Float32Array(normals), 'VEC3', F);
const index = add(new Uint16Array(indices), 'SCALAR', 5123);
const inflateAccessor = add(new Float32Array(inflate), 'VEC3', F, bounds(inflate));
const squashAccessor = add(new Float32Array(squash), 'VEC3', F, bounds(squash));
const squashNormalAccessor = add(new Float32Array(squashNormals), 'VEC3', F);
const times = add(new Float32Array([0, 1, 2]), 'SCALAR', F, { min: [0], max: [2] });
const weights = add(new Float32Array([0, 0, 1, 0.5, 0, 0]), 'SCALAR', F);

const json = {
  asset: { version: '2.0', generator: 'hullpack tests/web/make_morph_glb.mjs' },
  scene: 0,
  scenes: [{ nodes: [0] }],
  nodes: [{ name: 'blob', mesh: 0 }],
  meshes: [{
    name: 'blob',
    primitives: [{
      attributes: { POSITION: position, NORMAL: normal },
      indices: index,
      targets: [{ POSITION: inflateAccessor }, { POSITION: squashAccessor, NORMAL: squashNormalAccessor }],
    }],
    weights: [0, 0],
    extras: { targetNames: ['inflate', 'squash'] },
  }],
  animations: [{
    name: 'breathe',
    samplers: [{ input: times, output: weights }],
    channels: [{ sampler: 0, target: { node: 0, path: 'weights' } }],
  }],
  buffers: [{ byteLength: length }],
  bufferViews,
  accessors,
};
fs.writeFileSync(a.out, glbBytes(json, Buffer.concat(chunks)));
