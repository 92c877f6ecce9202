// make_glb.mjs: builds a packed GLB (docs/packed-gltf.md) for the browser test from o3dgc streams
// written by test_o3dgc (the C++ encoder of this build), with collision hulls in the earlier stream
// form (HULLPACK_mesh_compression groups with compactVertices) that files of the previous release
// carry and every reader keeps reading. The sample page shows `hullpack pack` outputs instead.
//
//   node tests/web/make_glb.mjs --encoder build/tools/test_o3dgc/test_o3dgc \
//        --ref build/tests/web/web_decode_ref --mesh samples/torus.obj --out samples/web/dist/torus.glb
//
// The render mesh is one primitive with HULLPACK_mesh_compression; two boxes around the two
// halves of the mesh (split along its longest axis) share one hull stream, one `group` each, and are
// listed as OMI_physics_shape convex shapes referenced by OMI_physics_body colliders on child nodes.
// Writes <out> and <out>.ref.json (what the C++ decoder gives for each primitive) and
// <out minus .glb>.s3d (the render stream alone).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { glbBytes } from './glb_container.mjs';

function args() {
  const a = {};
  const v = process.argv.slice(2);
  for (let i = 0; i + 1 < v.length; i += 2) a[v[i].replace(/^--/, '')] = v[i + 1];
  for (const k of ['encoder', 'ref', 'mesh', 'out']) {
    if (!a[k]) {
      console.error(`make_glb: --${k} is required`);
      process.exit(64);
    }
  }
  return a;
}

function encode(encoder, ref, objPath) {
  execFileSync(encoder, ['-c', '-st', 'binary', '-i', objPath], { stdio: ['ignore', 'ignore', 'inherit'], timeout: 120000 });
  const s3d = objPath.replace(/\.obj$/, '.s3d');
  const json = JSON.parse(execFileSync(ref, [s3d], { encoding: 'utf8', timeout: 120000 }));
  return { bytes: fs.readFileSync(s3d), ref: json, path: s3d };
}

function boxObj(ref) {
  const ext = [0, 1, 2].map((c) => ref.max[c] - ref.min[c]);
  const axis = ext.indexOf(Math.max(...ext));
  const mid = (ref.min[axis] + ref.max[axis]) / 2;
  let text = '';
  let base = 0;
  for (const [h, lo, hi] of [[0, ref.min[axis], mid], [1, mid, ref.max[axis]]]) {
    const min = [...ref.min];
    const max = [...ref.max];
    min[axis] = lo;
    max[axis] = hi;
    for (let i = 0; i < 8; ++i) {
      text += `v ${(i & 1 ? max : min)[0]} ${(i & 2 ? max : min)[1]} ${(i & 4 ? max : min)[2]}\n`;
    }
    text += `usemtl hull${h}\n`;
    const quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    for (const q of quads) {
      const [a, b, c, d] = q.map((i) => base + i + 1);
      text += `f ${a} ${b} ${c}\nf ${a} ${c} ${d}\n`;
    }
    base += 8;
  }
  return text;
}

function main() {
  const a = args();
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'hullpack-glb-'));
  try {
    const renderObj = path.join(work, 'render.obj');
    fs.copyFileSync(a.mesh, renderObj);
    const render = encode(a.encoder, a.ref, renderObj);
    const hullObj = path.join(work, 'hulls.obj');
    fs.writeFileSync(hullObj, boxObj(render.ref));
    const hulls = encode(a.encoder, a.ref, hullObj);

    const chunks = [];
    let offset = 0;
    const bufferViews = [];
    for (const s of [render.bytes, hulls.bytes]) {
      bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: s.length });
      const padded = Buffer.alloc((s.length + 3) & ~3);
      s.copy(padded);
      chunks.push(padded);
      offset += padded.length;
    }
    const bin = Buffer.concat(chunks);
    const accessors = [];
    const acc = (def) => accessors.push(def) - 1;
    const r = render.ref;
    const attrs = { POSITION: acc({ componentType: 5126, count: r.vertices, type: 'VEC3', min: r.min, max: r.max }) };
    const ids = { POSITION: 0 };
    let nextId = 1;
    if (r.normals) {
      attrs.NORMAL = acc({ componentType: 5126, count: r.vertices, type: 'VEC3' });
      ids.NORMAL = nextId++;
    }
    let uvSet = 0;
    for (const f of r.float_attributes) {
      if (f.semantic === 3 && f.dimension === 2) {
        attrs[`TEXCOORD_${uvSet}`] = acc({ componentType: 5126, count: r.vertices, type: 'VEC2' });
        ids[`TEXCOORD_${uvSet++}`] = nextId;
      }
      ++nextId;
    }
    const meshes = [{
      name: 'render',
      primitives: [{
        attributes: attrs,
        indices: acc({ componentType: 5125, count: 3 * r.triangles, type: 'SCALAR' }),
        material: 0,
        extensions: { HULLPACK_mesh_compression: { bufferView: 0, attributes: ids } },
      }],
    }];
    const nodes = [{ name: 'render', mesh: 0, children: [] }];
    const shapes = [];
    for (const g of hulls.ref.groups) {
      const m = meshes.push({
        name: `hull${g.id}`,
        primitives: [{
          attributes: { POSITION: acc({ componentType: 5126, count: g.vertices, type: 'VEC3', min: g.min, max: g.max }) },
          indices: acc({ componentType: 5125, count: 3 * g.triangles, type: 'SCALAR' }),
          extensions: { HULLPACK_mesh_compression: { bufferView: 1, attributes: { POSITION: 0 }, group: g.id, compactVertices: true } },
        }],
      }) - 1;
      const s = shapes.push({ type: 'convex', convex: { mesh: m } }) - 1;
      nodes[0].children.push(nodes.push({ name: `hull${g.id}`, extensions: { OMI_physics_body: { collider: { shape: s } } } }) - 1);
    }
    const doc = {
      asset: { version: '2.0', generator: 'hullpack tests/web/make_glb.mjs' },
      extensionsUsed: ['HULLPACK_mesh_compression', 'OMI_physics_body', 'OMI_physics_shape'],
      extensionsRequired: ['HULLPACK_mesh_compression'],
      extensions: { OMI_physics_shape: { shapes } },
      scene: 0,
      scenes: [{ nodes: [0] }],
      nodes,
      meshes,
      materials: [{ name: 'default', pbrMetallicRoughness: { baseColorFactor: [0.8, 0.55, 0.3, 1], metallicFactor: 0.1, roughnessFactor: 0.6 } }],
      accessors,
      bufferViews,
      buffers: [{ byteLength: bin.length }],
    };
    fs.mkdirSync(path.dirname(path.resolve(a.out)), { recursive: true });
    const glb = glbBytes(doc, bin);
    fs.writeFileSync(a.out, glb);
    fs.copyFileSync(render.path, a.out.replace(/\.glb$/, '') + '.s3d');
    fs.writeFileSync(`${a.out}.ref.json`, JSON.stringify({ render: r, hulls: hulls.ref.groups }, null, 1));
    console.log(`make_glb: wrote ${a.out} (${glb.length} bytes; ${r.vertices} vertices, ${r.triangles} triangles, ${hulls.ref.groups.length} hulls)`);
  } finally {
    fs.rmSync(work, { recursive: true, force: true });
  }
}

main();
