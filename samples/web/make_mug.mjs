// make_mug.mjs: writes a mug as an OBJ, a corpus-like model for the sample page (a concave body
// -- the inside must stay empty for things dropped into it -- and a handle with a hole, two closed
// parts that overlap where the handle meets the wall).
//   node samples/web/make_mug.mjs OUT.obj
import fs from 'node:fs';

const out = process.argv[2];
if (!out) {
  console.error('usage: node make_mug.mjs OUT.obj');
  process.exit(64);
}
const v = [];
const f = [];
const vertex = (x, y, z) => v.push([x, y, z]) - 1;

// The body: a closed surface of revolution around z through the profile (r, z), outside then inside.
const R = 0.4;
const H = 0.9;
const wall = 0.05;
const floor = 0.06;
const profile = [[R, 0], [R, H], [R - wall, H], [R - wall, floor]];
const N = 48;
const ring = profile.map(([r, z]) => Array.from({ length: N }, (_, k) => {
  const a = (2 * Math.PI * k) / N;
  return vertex(r * Math.cos(a), r * Math.sin(a), z);
}));
for (let p = 0; p + 1 < profile.length; ++p) {
  for (let k = 0; k < N; ++k) {
    const k1 = (k + 1) % N;
    f.push([ring[p][k], ring[p][k1], ring[p + 1][k1]], [ring[p][k], ring[p + 1][k1], ring[p + 1][k]]);
  }
}
const bottom = vertex(0, 0, 0);
const inner = vertex(0, 0, floor);
const last = ring[profile.length - 1];
for (let k = 0; k < N; ++k) {
  const k1 = (k + 1) % N;
  f.push([bottom, ring[0][k1], ring[0][k]]);
  f.push([inner, last[k], last[k1]]);
}

// The handle: a torus in the xz plane, its inner side sunk into the wall.
const major = 0.2;
const minor = 0.045;
const cx = R + 0.12;
const cz = H / 2;
const U = 32;
const W = 12;
const t = [];
for (let i = 0; i < U; ++i) {
  const a = (2 * Math.PI * i) / U;
  t.push([]);
  for (let j = 0; j < W; ++j) {
    const b = (2 * Math.PI * j) / W;
    const r = major + minor * Math.cos(b);
    t[i].push(vertex(cx + r * Math.cos(a), minor * Math.sin(b), cz + r * Math.sin(a)));
  }
}
for (let i = 0; i < U; ++i) {
  for (let j = 0; j < W; ++j) {
    const i1 = (i + 1) % U;
    const j1 = (j + 1) % W;
    f.push([t[i][j], t[i1][j], t[i1][j1]], [t[i][j], t[i1][j1], t[i][j1]]);
  }
}

const text = v.map(([x, y, z]) => `v ${x.toFixed(6)} ${y.toFixed(6)} ${z.toFixed(6)}`).join('\n') +
  '\n' + f.map((tri) => `f ${tri.map((i) => i + 1).join(' ')}`).join('\n') + '\n';
fs.writeFileSync(out, text);
console.log(`make_mug: wrote ${out} (${v.length} vertices, ${f.length} triangles)`);
