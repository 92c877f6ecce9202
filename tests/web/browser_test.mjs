// browser_test.mjs: drives headless Chromium (playwright-core + Debian's /usr/bin/chromium) over the
// viewer page and the WebAssembly decoder, and compares with the C++ decoder's figures.
//   node tests/web/browser_test.mjs --repo DIR --work DIR [--chromium /usr/bin/chromium]
// --work holds torus.glb, torus.s3d and torus.glb.ref.json (tests/web/make_glb.mjs) and receives
// the screenshots. Exit 0 pass, 1 fail, 77 skip.
import fs from 'node:fs';
import path from 'node:path';
import { requirePlaywright, startSession } from './chromium_session.mjs';

const a = {};
for (let i = 2; i + 1 < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
const repo = path.resolve(a.repo || '.');
const work = path.resolve(a.work || '.');
const chromiumPath = a.chromium || '/usr/bin/chromium';

let failures = 0;
function check(cond, what) {
  console.log(`${cond ? 'ok  ' : 'FAIL'} ${what}`);
  if (!cond) failures += 1;
}
const close = (x, y, tol = 1e-5) => Math.abs(x - y) <= tol * Math.max(1, Math.abs(y));
const closeVec = (u, v) => u.length === v.length && u.every((x, i) => close(x, v[i]));

const playwright = await requirePlaywright({ chromiumPath, repo });
const ref = JSON.parse(fs.readFileSync(path.join(work, 'torus.glb.ref.json'), 'utf8'));

const session = await startSession({
  playwright, chromiumPath, repo, work, profilePrefix: 'hullpack-chromium-', what: 'browser test', timeoutMs: 150000,
});
const { url } = session;
try {
  // Nothing but the local server (session.launch aborts every other request).
  const page = await session.launch({
    extraArgs: ['--enable-unsafe-swiftshader', '--use-angle=swiftshader'],
    viewport: { width: 800, height: 600 },
  });
  const context = session.context;
  page.setDefaultTimeout(60000);
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });

  // 1. The viewer on the packed GLB (main-thread decoder, hulls shown).
  await page.goto(`${url}/samples/web/index.html?glb=/__work/torus.glb&hulls=1`);
  const info = await page.evaluate(() => window.hullpackViewer.ready);
  console.log(`glb: ${info.vertices} vertices, ${info.triangles} triangles, decode ${info.decodeMs.toFixed(2)} ms, ${info.hulls.length} hulls`);
  check(info.vertices === ref.render.vertices, `glb vertices ${info.vertices} == C++ ${ref.render.vertices}`);
  check(info.triangles === ref.render.triangles, `glb triangles ${info.triangles} == C++ ${ref.render.triangles}`);
  check(closeVec(info.min, ref.render.min) && closeVec(info.max, ref.render.max),
    `glb bounds ${JSON.stringify([info.min, info.max])} == C++ ${JSON.stringify([ref.render.min, ref.render.max])}`);
  check(info.hulls.length === ref.hulls.length, `hulls ${info.hulls.length} == ${ref.hulls.length}`);
  ref.hulls.forEach((h, i) => {
    const g = info.hulls[i] || {};
    check(g.vertices === h.vertices && g.triangles === h.triangles && closeVec(g.min || [], h.min) && closeVec(g.max || [], h.max),
      `hull ${i}: ${g.vertices}/${g.triangles} == C++ ${h.vertices}/${h.triangles}, bounds match`);
  });
  // Something was drawn: count pixels that differ from the background.
  const drawn = await page.evaluate(() => {
    const src = window.hullpackViewer.renderer.domElement;
    const c = document.createElement('canvas');
    c.width = src.width;
    c.height = src.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(src, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - 0x20) + Math.abs(d[i + 1] - 0x24) + Math.abs(d[i + 2] - 0x2a) > 24) ++n;
    }
    return n / (c.width * c.height);
  });
  check(drawn > 0.02, `model visible: ${(100 * drawn).toFixed(1)}% of the canvas drawn`);
  await page.screenshot({ path: path.join(work, 'viewer_glb.png') });
  console.log(`screenshot: ${path.join(work, 'viewer_glb.png')}`);

  // 2. The decoder module directly: main thread vs worker vs C++, and errors.
  const direct = await page.evaluate(async () => {
    const m = await import('/web/hullpack_decoder.js');
    const wasmUrl = '/samples/web/dist/hullpack_decoder_wasm.wasm';
    const bytes = new Uint8Array(await (await fetch('/__work/torus.s3d')).arrayBuffer());
    const dec = await m.createDecoder({ wasmUrl });
    const main = dec.decode(bytes);
    const worker = await m.createWorkerDecoder({ wasmUrl });
    const w = await worker.decode(bytes);
    const errorOf = async (fn) => { try { await fn(); return 'no error'; } catch (e) { return `${e.name}:${e.status}`; } };
    const junk = new Uint8Array(64).map((_, i) => (i * 37) & 255);
    const errs = {
      junk: await errorOf(() => dec.decode(junk)),
      truncated: await errorOf(() => dec.decode(bytes.subarray(0, bytes.length >> 1))),
      flipped: await errorOf(() => { const b = bytes.slice(); b[b.length - 5] ^= 0x55; return dec.decode(b); }),
      workerJunk: await errorOf(() => worker.decode(junk)),
      // Format 1.3 (max_compression): decoded exactly as the C++ decoder's conformance text.
      conformance13: await (async () => {
        const dir = '/tests/o3dgc/conformance/1.3/max_compression';
        const s3d = new Uint8Array(await (await fetch(`${dir}.s3d`)).arrayBuffer());
        const text = await (await fetch(`${dir}.txt`)).text();
        const d = dec.decode(s3d);
        const v = [], f = [];
        for (const line of text.split('\n')) {
          const w = line.split(' ');
          if (w[0] === 'v') v.push(...w.slice(1).map((x) => Math.fround(Number(x))));
          if (w[0] === 'f') f.push(...w.slice(1).map(Number));
        }
        const same = v.length === d.positions.length && v.every((x, i) => x === d.positions[i]) &&
          f.length === d.indices.length && f.every((x, i) => x === d.indices[i]);
        return same ? 'same' : `differs (${d.positions.length} / ${v.length} coordinates)`;
      })().catch((e) => `${e.name}:${e.status ?? e.message}`),
      // An original Open3DGC stream: this build leaves their decoder out (HULLPACK_WASM_LEGACY).
      legacy: await errorOf(async () => dec.decode(new Uint8Array(await (await fetch('/tests/o3dgc/vectors/cup.binary.s3d')).arrayBuffer()))),
    };
    // Mutated streams (fixed seed, CRC check off so the decoder proper sees them): each must fail
    // cleanly or decode; anything but HullpackDecodeError is a wasm trap.
    let seed = 12345;
    const rnd = () => ((seed = (seed * 1103515245 + 12345) >>> 0) / 4294967296);
    const traps = [];
    for (let i = 0; i < 1000; ++i) {
      const b = bytes.slice(0, 1 + Math.floor(rnd() * bytes.length));
      for (let k = 0; k < 1 + (i % 4); ++k) b[Math.floor(rnd() * b.length)] = Math.floor(rnd() * 256);
      try { dec.decode(b, { verifyChecksum: false }); } catch (e) { if (e.name !== 'HullpackDecodeError') traps.push(String(e)); }
    }
    errs.traps = traps.slice(0, 3).join(' | ');
    errs.trapCount = traps.length;
    const again = dec.decode(bytes); // the decoder still works after errors
    worker.terminate();
    const same = (x, y) => x.length === y.length && x.every((v, i) => v === y[i]);
    return {
      main: { nv: main.numVertices, nt: main.numTriangles, uvs: main.uvs.length, normals: !!main.normals, ...m.bounds(main.positions) },
      workerSame: same(w.positions, main.positions) && same(w.indices, main.indices) && same(w.normals, main.normals) && same(w.uvs[0], main.uvs[0]),
      againSame: same(again.positions, main.positions) && same(again.indices, main.indices),
      maxIndex: main.indices.reduce((x, y) => Math.max(x, y), 0),
      errs,
    };
  });
  const r = ref.render;
  check(direct.main.nv === r.vertices && direct.main.nt === r.triangles, `stream decode ${direct.main.nv}/${direct.main.nt} == C++ ${r.vertices}/${r.triangles}`);
  check(closeVec(direct.main.min, r.min) && closeVec(direct.main.max, r.max), 'stream bounds == C++');
  check(direct.main.normals === r.normals && direct.main.uvs === r.float_attributes.filter((f) => f.semantic === 3).length, 'stream attributes == C++');
  check(direct.maxIndex < direct.main.nv, 'indices in range');
  check(direct.workerSame, 'worker decode == main-thread decode');
  check(direct.againSame, 'decoder reusable after errors');
  check(direct.errs.junk === 'HullpackDecodeError:bad_magic', `junk -> ${direct.errs.junk}`);
  check(/^HullpackDecodeError:(truncated|corrupt|checksum_mismatch|limit_exceeded)$/.test(direct.errs.truncated), `truncated -> ${direct.errs.truncated}`);
  check(/^HullpackDecodeError:/.test(direct.errs.flipped), `flipped byte -> ${direct.errs.flipped}`);
  check(direct.errs.trapCount === 0, `1000 mutated streams: no wasm trap${direct.errs.trapCount ? `: ${direct.errs.traps}` : ''}`);
  check(direct.errs.workerJunk === 'HullpackDecodeError:bad_magic', `worker junk -> ${direct.errs.workerJunk}`);
  check(direct.errs.legacy === 'HullpackDecodeError:unsupported', `original Open3DGC stream -> ${direct.errs.legacy}`);
  check(direct.errs.conformance13 === 'same', `format 1.3 conformance vector -> ${direct.errs.conformance13}`);

  // 3. The viewer on the bare stream, decoded in a worker.
  const page2 = await context.newPage();
  page2.on('pageerror', (e) => errors.push(String(e)));
  await page2.goto(`${url}/samples/web/index.html?stream=/__work/torus.s3d&worker=1`);
  const info2 = await page2.evaluate(() => window.hullpackViewer.ready);
  check(info2.vertices === r.vertices && info2.triangles === r.triangles, `viewer stream+worker ${info2.vertices}/${info2.triangles}`);
  await page2.screenshot({ path: path.join(work, 'viewer_stream.png') });

  // 4. GLBs written by `hullpack pack` (both collider forms): the figures their accessors state
  // (count, min/max of the decoded data, per docs/packed-gltf.md) must be what the browser decodes,
  // with one hull per collider node.
  const packedFiles = ['packed.glb', 'packed_khr.glb'].filter((f) => fs.existsSync(path.join(work, f)));
  for (const file of packedFiles) {
    const glb = fs.readFileSync(path.join(work, file));
    const doc = JSON.parse(glb.subarray(20, 20 + glb.readUInt32LE(12)).toString('utf8'));
    const colliderMesh = (n) => {
      const omi = n.extensions?.OMI_physics_body?.collider;
      if (omi?.shape !== undefined) {
        const s = doc.extensions?.OMI_physics_shape?.shapes?.[omi.shape];
        return s?.convex?.mesh ?? s?.trimesh?.mesh;
      }
      const g = n.extensions?.KHR_physics_rigid_bodies?.collider?.geometry;
      return g?.node !== undefined ? doc.nodes[g.node]?.mesh : g?.mesh;
    };
    const colliderNodes = (doc.nodes || []).filter((n) => colliderMesh(n) !== undefined);
    const hullMeshes = new Set(colliderNodes.map(colliderMesh));
    let nv = 0;
    let nt = 0;
    for (const node of doc.nodes || []) {
      if (node.mesh === undefined || hullMeshes.has(node.mesh)) continue;
      for (const prim of doc.meshes[node.mesh].primitives) {
        nv += doc.accessors[prim.attributes.POSITION].count;
        nt += prim.indices !== undefined ? doc.accessors[prim.indices].count / 3 : doc.accessors[prim.attributes.POSITION].count / 3;
      }
    }
    const page3 = await context.newPage();
    page3.on('pageerror', (e) => errors.push(String(e)));
    await page3.goto(`${url}/samples/web/index.html?glb=/__work/${file}&hulls=1`);
    const info3 = await page3.evaluate(() => window.hullpackViewer.ready);
    check(info3.vertices === nv && info3.triangles === nt, `hullpack pack ${file}: ${info3.vertices}/${info3.triangles} == accessors ${nv}/${nt}`);
    check(colliderNodes.length > 0 && info3.hulls.length === colliderNodes.length,
      `hullpack pack ${file}: ${info3.hulls.length} hulls == ${colliderNodes.length} collider nodes`);
    // Each hull: the points its accessor states (a POINTS primitive, no hullpack extension), shown
    // as their convex hull.
    const hullOk = info3.hulls.every((h, k) => {
      const prim = doc.meshes[colliderMesh(colliderNodes[k])].primitives[0];
      return h.points === doc.accessors[prim.attributes.POSITION].count && prim.mode === 0 &&
        !prim.extensions && h.triangles >= 4;
    });
    check(hullOk, `hullpack pack ${file}: every hull has its accessor's points, plain glTF, shown as a closed hull`);
    await page3.screenshot({ path: path.join(work, file.replace(/\.glb$/, '.png')) });
  }
  if (!packedFiles.length) console.log('note: no packed.glb (hullpack pack not available); checked the make_glb.mjs GLB only');

  // 5. Every packed GLB against the C++ reader (`hullpack unpack` wrote X.ref.glb: the same
  // document, each compressed primitive decoded into plain accessors, skin weights renormalized).
  // (a) What the plugin hands three.js for each compressed accessor (component type, item size,
  // normalized flag, every byte) must be the C++ accessor, with the decoder on the main thread and
  // in the worker. It is read straight from the plugin, before three's SkinnedMesh rescales float
  // weights in place. (b) The whole GLTFLoader path: every mesh's geometry equals that of the
  // reference file loaded by three without the plugin.
  const refPairs = ['skinned.packed', 'packed', 'packed_khr', 'packed_fast']
    .filter((f) => fs.existsSync(path.join(work, `${f}.glb`)) && fs.existsSync(path.join(work, `${f}.ref.glb`)));
  const TYPED = { 5120: 'Int8Array', 5121: 'Uint8Array', 5122: 'Int16Array', 5123: 'Uint16Array', 5125: 'Uint32Array', 5126: 'Float32Array' };
  const COMPONENTS = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT2: 4, MAT3: 9, MAT4: 16 };
  const readGlb = (file) => {
    const glb = fs.readFileSync(path.join(work, file));
    const jsonLength = glb.readUInt32LE(12);
    const doc = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
    const binStart = 20 + jsonLength + 8;
    return { doc, bin: glb.subarray(binStart, binStart + glb.readUInt32LE(20 + jsonLength)) };
  };
  for (const base of refPairs) {
    const packed = readGlb(`${base}.glb`);
    const refGlb = readGlb(`${base}.ref.glb`);
    // The accessors the streams supply: those without data in the packed file.
    const expected = {};
    packed.doc.accessors.forEach((acc, i) => {
      if (acc.bufferView !== undefined) return;
      const r = refGlb.doc.accessors[i];
      const bv = refGlb.doc.bufferViews[r.bufferView];
      const size = { 5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4 }[r.componentType];
      const n = COMPONENTS[r.type];
      if (bv.byteStride && bv.byteStride !== n * size) throw new Error(`${base}.ref.glb accessor ${i}: interleaved`);
      const start = (bv.byteOffset || 0) + (r.byteOffset || 0);
      expected[i] = {
        type: TYPED[r.componentType], itemSize: n, normalized: r.normalized === true,
        bytes: [...refGlb.bin.subarray(start, start + r.count * n * size)],
        semantic: null,
      };
    });
    for (const m of packed.doc.meshes) {
      for (const prim of m.primitives) {
        for (const [name, i] of Object.entries(prim.attributes)) if (expected[i]) expected[i].semantic = name;
        if (prim.indices !== undefined && expected[prim.indices]) expected[prim.indices].semantic = 'indices';
      }
    }
    const page5 = await context.newPage();
    page5.on('pageerror', (e) => errors.push(String(e)));
    await page5.goto(`${url}/samples/web/index.html?glb=/__work/${base}.glb&worker=1`);
    await page5.evaluate(() => window.hullpackViewer.ready);
    const got = await page5.evaluate(async ({ base: b }) => {
      const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
      const dm = await import('/web/hullpack_decoder.js');
      const { HullpackMeshCompressionPlugin } = await import('/web/hullpack_gltf_plugin.js');
      const wasmUrl = '/samples/web/dist/hullpack_decoder_wasm.wasm';
      const buffer = await (await fetch(`/__work/${b}.glb`)).arrayBuffer();
      const view = new DataView(buffer);
      const jsonLength = view.getUint32(12, true);
      const json = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 20, jsonLength)));
      const binStart = 20 + jsonLength + 8;
      // The parser interface beforeRoot() uses: the JSON, bufferViews, and loadAccessor (replaced).
      const parser = {
        json,
        getDependency: async (type, i) => {
          if (type !== 'bufferView') throw new Error(`unexpected dependency ${type}`);
          const bv = json.bufferViews[i];
          return buffer.slice(binStart + (bv.byteOffset || 0), binStart + (bv.byteOffset || 0) + bv.byteLength);
        },
        loadAccessor: async () => { throw new Error('loadAccessor before beforeRoot finished'); },
      };
      const accessorsOf = async (decoder) => {
        const plugin = new HullpackMeshCompressionPlugin(parser, decoder);
        await plugin.beforeRoot();
        const out = {};
        for (const [i, a] of plugin.accessors) {
          out[i] = { type: a.array.constructor.name, itemSize: a.itemSize, normalized: a.normalized,
            bytes: [...new Uint8Array(a.array.buffer, a.array.byteOffset, a.array.byteLength)] };
        }
        return out;
      };
      const mainDecoder = await dm.createDecoder({ wasmUrl });
      const main = await accessorsOf(mainDecoder);
      // An accessor whose count is not the decoded data's is rejected (as the C++ reader does).
      const bad = JSON.parse(JSON.stringify(json));
      const victim = bad.accessors.findIndex((acc) => acc.bufferView === undefined);
      bad.accessors[victim].count += 1;
      let badCount = 'accepted';
      try {
        await new HullpackMeshCompressionPlugin({ ...parser, json: bad }, mainDecoder).beforeRoot();
      } catch (e) {
        badCount = e.message;
      }
      const worker = await dm.createWorkerDecoder({ wasmUrl });
      const inWorker = await accessorsOf(worker);
      // (b) Whole loader: a digest of every mesh's geometry (all attributes and the index).
      const digest = (a) => {
        if (!a) return 'none';
        if (a.isInterleavedBufferAttribute) return 'interleaved';
        const bytes = new Uint8Array(a.array.buffer, a.array.byteOffset, a.array.byteLength);
        let h = 2166136261;
        for (let k = 0; k < bytes.length; ++k) h = Math.imul(h ^ bytes[k], 16777619) >>> 0;
        return `${a.array.constructor.name}/${a.itemSize}/${a.normalized}/${a.count}/${h.toString(16)}`;
      };
      const geometries = async (fileUrl, decoder) => {
        const loader = new GLTFLoader();
        if (decoder) loader.register((p) => new HullpackMeshCompressionPlugin(p, decoder));
        const gltf = await loader.loadAsync(fileUrl);
        const out = [];
        for (let i = 0; i < (gltf.parser.json.meshes || []).length; ++i) {
          const o = await gltf.parser.getDependency('mesh', i);
          for (const m of o.isMesh ? [o] : o.children.filter((c) => c.isMesh)) {
            const g = { index: digest(m.geometry.index) };
            for (const [name, a] of Object.entries(m.geometry.attributes)) g[name] = digest(a);
            out.push(g);
          }
        }
        return out;
      };
      const loaded = {
        ref: await geometries(`/__work/${b}.ref.glb`, null),
        main: await geometries(`/__work/${b}.glb`, mainDecoder),
        worker: await geometries(`/__work/${b}.glb`, worker),
      };
      worker.terminate();
      return { main, inWorker, loaded, badCount };
    }, { base });
    for (const [where, accs] of [['main thread', got.main], ['worker', got.inWorker]]) {
      const wrong = [];
      for (const [i, e] of Object.entries(expected)) {
        const g = accs[i];
        if (!g) { wrong.push(`accessor ${i} (${e.semantic}) not supplied`); continue; }
        if (g.type !== e.type || g.itemSize !== e.itemSize || g.normalized !== e.normalized) {
          wrong.push(`accessor ${i} (${e.semantic}) ${g.type}/${g.itemSize}/${g.normalized} != C++ ${e.type}/${e.itemSize}/${e.normalized}`);
          continue;
        }
        const n = e.bytes.length;
        let diff = g.bytes.length === n ? 0 : -1;
        let first = -1;
        for (let k = 0; diff >= 0 && k < n; ++k) if (g.bytes[k] !== e.bytes[k]) { ++diff; if (first < 0) first = k; }
        if (diff) {
          let detail = diff < 0 ? `${g.bytes.length} bytes != C++ ${n}` : `${diff} bytes differ`;
          if (first >= 0 && e.type === 'Float32Array') {
            const f = (bytes) => new Float32Array(Uint8Array.from(bytes.slice(first & ~15, (first & ~15) + 16)).buffer);
            detail += `, first at value ${first >> 2}: [${[...f(g.bytes)]}] != C++ [${[...f(e.bytes)]}]`;
          }
          wrong.push(`accessor ${i} (${e.semantic}): ${detail}`);
        }
      }
      const names = [...new Set(Object.values(expected).map((e) => e.semantic))].sort().join(' ');
      check(wrong.length === 0 && Object.keys(expected).length > 0,
        `${base}.glb, ${where}: the plugin's ${Object.keys(expected).length} decoded accessors (${names}) == C++ reader's, byte for byte${wrong.length ? `: ${wrong.slice(0, 4).join('; ')}` : ''}`);
    }
    const same = (x, y) => JSON.stringify(x) === JSON.stringify(y);
    check(got.loaded.ref.length > 0 && same(got.loaded.main, got.loaded.ref) && same(got.loaded.worker, got.loaded.ref),
      `${base}.glb through GLTFLoader (main thread and worker): every mesh's geometry == the C++-decoded file's` +
      (same(got.loaded.main, got.loaded.ref) ? '' : `: ${JSON.stringify(got.loaded.main).slice(0, 300)} != ${JSON.stringify(got.loaded.ref).slice(0, 300)}`));
    check(/does not match the stream/.test(got.badCount), `${base}.glb with an accessor count off by one: ${got.badCount}`);
    if (base === 'skinned.packed') await page5.screenshot({ path: path.join(work, 'skinned.png') });
  }
  if (fs.existsSync(path.join(work, 'skinned.packed.glb'))) {
    check(refPairs.includes('skinned.packed'), 'skinned GLB compared with the C++ reader');
  }

  check(errors.length === 0, `no page errors${errors.length ? `: ${errors.join(' | ')}` : ''}`);
} catch (e) {
  console.log(`FAIL: ${e && e.stack ? e.stack : e}`);
  failures += 1;
} finally {
  await session.close();
}
console.log(failures ? `${failures} check(s) failed` : 'all browser checks passed');
process.exit(failures ? 1 : 0);
