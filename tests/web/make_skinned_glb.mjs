// make_skinned_glb.mjs: writes a small skinned glTF (GLB) for the browser test, generated in code:
// a closed tube along +Y bent over a chain of 4 joints, two materials (lower and upper half, so
// `hullpack pack` writes two primitives that share one stream by `group`), float WEIGHTS_0 and
// UNSIGNED_BYTE JOINTS_0. The weights are chosen to exercise the packed format's weight rule
// (docs/packed-gltf.md): 4 arbitrary influences (their quantized sum is almost never 1), equal
// largest weights (2 and 4 ties), a single influence, tiny ones, and all-zero vertices.
//
//   node tests/web/make_skinned_glb.mjs --out WORK/skinned.glb
import fs from 'node:fs';
import path from 'node:path';
import { glbBytes } from './glb_container.mjs';

const a = {};
for (let i = 2; i + 1 < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
if (!a.out) {
  console.error('usage: make_skinned_glb.mjs --out FILE.glb');
  process.exit(64);
}

const SEGMENTS = 24;   // around the tube
const RINGS = 33;      // along it
const HEIGHT = 2;
const RADIUS = 0.25;
const JOINTS = 4;

let seed = 20240611;
const rnd = () => ((seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 4294967296);

const positions = [];
const normals = [];
const joints = [];
const weights = [];
function weightsFor(v, y) {
  const kind = v % 11;
  // Influences of the joints by height (a smooth skin), then perturbed.
  const t = (y / HEIGHT) * (JOINTS - 1);
  const base = [0, 1, 2, 3].map((j) => Math.max(0, 1 - Math.abs(t - j)) + 0.05 * rnd());
  if (v === 40 || v === 41) return [0, 0, 0, 0];
  if (kind === 3) return [0.5, 0.5, 0, 0];
  if (kind === 5) return [0.25, 0.25, 0.25, 0.25];
  if (kind === 7) return [0, 1, 0, 0];
  if (kind === 9) return [1 / 3, 1 / 3, 1 / 3, 0];
  if (kind === 1) return [0.999, 0.0004, 0.0003, 0.0003];
  const s = base.reduce((x, y2) => x + y2, 0);
  return base.map((w) => Math.fround(w / s));
}
for (let r = 0; r < RINGS; ++r) {
  const y = (HEIGHT * r) / (RINGS - 1);
  for (let s = 0; s < SEGMENTS; ++s) {
    const phi = (2 * Math.PI * s) / SEGMENTS;
    const bend = 0.15 * Math.sin((Math.PI * y) / HEIGHT);
    positions.push(RADIUS * Math.cos(phi) + bend, y, RADIUS * Math.sin(phi));
    normals.push(Math.cos(phi), 0, Math.sin(phi));
    const v = positions.length / 3 - 1;
    weights.push(...weightsFor(v, y));
    // A per-vertex permutation of the joints, so the stream's joint ids vary too.
    const order = [0, 1, 2, 3];
    if (v % 2) order.reverse();
    joints.push(...order);
    if (v % 2) weights.splice(weights.length - 4, 4, ...weights.slice(-4).reverse());
  }
}
// Caps: one centre vertex per end.
const caps = [[0, -1], [HEIGHT, 1]];
const capIndex = [];
for (const [y, ny] of caps) {
  capIndex.push(positions.length / 3);
  positions.push(0.15 * Math.sin((Math.PI * y) / HEIGHT), y, 0);
  normals.push(0, ny, 0);
  joints.push(0, 1, 2, 3);
  weights.push(...(y === 0 ? [1, 0, 0, 0] : [0, 0, 0, 1]));
}
const lower = [];
const upper = [];
for (let r = 0; r + 1 < RINGS; ++r) {
  const out = r < (RINGS - 1) / 2 ? lower : upper;
  for (let s = 0; s < SEGMENTS; ++s) {
    const a0 = r * SEGMENTS + s;
    const a1 = r * SEGMENTS + ((s + 1) % SEGMENTS);
    const b0 = a0 + SEGMENTS;
    const b1 = a1 + SEGMENTS;
    out.push(a0, b0, a1, a1, b0, b1);
  }
}
for (let s = 0; s < SEGMENTS; ++s) {
  const n = (s + 1) % SEGMENTS;
  lower.push(capIndex[0], s, n);
  const top = (RINGS - 1) * SEGMENTS;
  upper.push(capIndex[1], top + n, top + s);
}

// Binary chunk: every array tightly packed, 4-byte aligned.
const parts = [];
let offset = 0;
const bufferViews = [];
const accessors = [];
function view(typed, target) {
  const bytes = Buffer.from(typed.buffer, typed.byteOffset, typed.byteLength);
  const padded = Buffer.alloc((bytes.length + 3) & ~3);
  bytes.copy(padded);
  parts.push(padded);
  const bv = { buffer: 0, byteOffset: offset, byteLength: bytes.length };
  if (target) bv.target = target;
  offset += padded.length;
  return bufferViews.push(bv) - 1;
}
function accessor(typed, componentType, type, count, extra = {}, target = 34962) {
  return accessors.push({ bufferView: view(typed, target), componentType, count, type, ...extra }) - 1;
}
const nv = positions.length / 3;
const min = [0, 1, 2].map((c) => Math.min(...positions.filter((_, i) => i % 3 === c).map(Math.fround)));
const max = [0, 1, 2].map((c) => Math.max(...positions.filter((_, i) => i % 3 === c).map(Math.fround)));
const attributes = {
  POSITION: accessor(new Float32Array(positions), 5126, 'VEC3', nv, { min, max }),
  NORMAL: accessor(new Float32Array(normals), 5126, 'VEC3', nv),
  JOINTS_0: accessor(new Uint8Array(joints), 5121, 'VEC4', nv),
  WEIGHTS_0: accessor(new Float32Array(weights), 5126, 'VEC4', nv),
};
const prims = [lower, upper].map((ix, m) => ({
  attributes,
  indices: accessor(new Uint16Array(ix), 5123, 'SCALAR', ix.length, {}, 34963),
  material: m,
}));
// Joint chain along +Y; inverse bind matrices undo each joint's rest translation.
const step = HEIGHT / (JOINTS - 1);
const ibm = new Float32Array(16 * JOINTS);
for (let j = 0; j < JOINTS; ++j) {
  ibm.set([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -j * step, 0, 1], 16 * j);
}
const nodes = [
  { name: 'tube', mesh: 0, skin: 0 },
  { name: 'joint0', children: [2] },
  { name: 'joint1', translation: [0, step, 0], children: [3] },
  { name: 'joint2', translation: [0, step, 0], children: [4] },
  { name: 'joint3', translation: [0, step, 0] },
];
const doc = {
  asset: { version: '2.0', generator: 'hullpack tests/web/make_skinned_glb.mjs' },
  scene: 0,
  scenes: [{ nodes: [0, 1] }],
  nodes,
  meshes: [{ name: 'tube', primitives: prims }],
  materials: [
    { name: 'lower', pbrMetallicRoughness: { baseColorFactor: [0.8, 0.4, 0.3, 1] } },
    { name: 'upper', pbrMetallicRoughness: { baseColorFactor: [0.3, 0.5, 0.8, 1] } },
  ],
  skins: [{ joints: [1, 2, 3, 4], skeleton: 1, inverseBindMatrices: accessor(ibm, 5126, 'MAT4', JOINTS, {}, null) }],
  accessors,
  bufferViews,
  buffers: [{ byteLength: offset }],
};
const bin = Buffer.concat(parts);
fs.mkdirSync(path.dirname(path.resolve(a.out)), { recursive: true });
fs.writeFileSync(a.out, glbBytes(doc, bin));
console.log(`make_skinned_glb: wrote ${a.out} (${nv} vertices, ${(lower.length + upper.length) / 3} triangles, ${JOINTS} joints)`);
