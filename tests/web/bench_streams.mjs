// bench_streams.mjs: the inputs of the decode benchmarks (bench.mjs in the browser, bench_cpu.mjs in
// Node): every .obj of a corpus folder (manifest.csv order when there is one) encoded twice from
// the same file, with this build's test_o3dgc (binary stream) and with Debian's draco_encoder, at
// the same bits (positions/normals/UVs), Draco at compression level `cl` (7 = its default).
// `--fast 1` encodes hullpack's streams with test_o3dgc -fast (EncodeParams::fast_decode).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { createRequire } from 'node:module';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

// Command-line flags --name value into an object.
export function parseArgs(argv) {
  const a = {};
  for (let i = 2; i + 1 < argv.length; i += 2) a[argv[i].replace(/^--/, '')] = argv[i + 1];
  return a;
}

// -> {dir, list: [{name, s3d, drc}] (file names in dir), settings}; the caller removes dir.
export function prepareStreams(a) {
  const corpus = path.resolve(a.corpus || path.join(repo, '../shared/corpus'));
  const encoder = path.resolve(a.encoder || path.join(repo, 'build/tools/test_o3dgc/test_o3dgc'));
  const bits = { qp: a.qp || '14', qn: a.qn || '10', qt: a.qt || '12' };
  const cl = a.cl || '7';
  const fast = a.fast === '1';
  let names;
  const manifest = path.join(corpus, 'manifest.csv');
  if (fs.existsSync(manifest)) {
    const rows = fs.readFileSync(manifest, 'utf8').trim().split('\n').slice(1).map((l) => l.split(','));
    names = rows.map((r) => r[1]).filter((f) => f.endsWith('.obj'));
  } else {
    names = fs.readdirSync(corpus).filter((f) => f.endsWith('.obj')).sort();
  }
  if (a.meshes) {
    const want = new Set(a.meshes.split(','));
    names = names.filter((f) => want.has(f.replace(/\.obj$/, '')));
  }
  if (!names.length) throw new Error(`no meshes in ${corpus}`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'hullpack-bench-'));
  const list = [];
  for (const file of names) {
    const name = file.replace(/\.obj$/, '');
    const obj = path.join(dir, file);
    fs.copyFileSync(path.join(corpus, file), obj);
    execFileSync(encoder, ['-c', '-st', 'binary', '-qc', bits.qp, '-qn', bits.qn, '-qt', bits.qt,
      ...(fast ? ['-fast'] : []), '-i', obj], { stdio: 'ignore' });
    execFileSync('draco_encoder', ['-i', obj, '-o', path.join(dir, `${name}.drc`), '-qp', bits.qp, '-qn', bits.qn,
      '-qt', bits.qt, '-cl', cl], { stdio: 'ignore' });
    list.push({ name, s3d: `${name}.s3d`, drc: `${name}.drc` });
  }
  return { dir, list, settings: { ...bits, dracoCl: cl, fastDecode: fast, corpus, encoder } };
}

export const median = (v) => {
  const s = [...v].sort((x, y) => x - y);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
export const fmt = (x) => (x < 10 ? x.toFixed(2) : x.toFixed(1));

// The decoders of the Node benchmarks (bench_cpu.mjs, bench_instructions.mjs), each
// {name, stream: 's3d' | 'drc', decode(bytes) -> [vertices, triangles, 'attr+attr']}: hullpack's
// wasm build from each folder of a.wasm (default samples/web/dist; a.only = 'hullpack' or 'draco'
// keeps one kind) and Draco's official WASM decoder (three's copy), driven by web/bench_draco.js
// as in the browser.
export async function nodeDecoders(a) {
  // The emscripten glue is built for web and worker only: look like a worker to it (wasmBinary is
  // passed, so nothing is fetched). Draco's wrapper wants CommonJS globals.
  globalThis.self = globalThis;
  globalThis.importScripts = () => {};
  globalThis.location = { href: pathToFileURL(`${repo}/`).href };
  globalThis.require = createRequire(import.meta.url);
  globalThis.__dirname = repo;
  const summary = (m) => [m.numVertices, m.numTriangles, m.attributes.map((x) => x.semantic).join('+')];
  const decoders = [];
  if (a.only !== 'draco') {
    const { decoderFromModule } = await import(pathToFileURL(path.join(repo, 'web/hullpack_decoder.js')).href);
    const dirs = (a.wasm || 'samples/web/dist').split(',').map((d) => path.resolve(repo, d));
    for (const d of dirs) {
      const { default: factory } = await import(`${pathToFileURL(path.join(d, 'hullpack_decoder_wasm.js')).href}?${decoders.length}`);
      const M = await factory({ wasmBinary: fs.readFileSync(path.join(d, 'hullpack_decoder_wasm.wasm')) });
      const dec = decoderFromModule(M);
      const name = dirs.length === 1 ? 'hullpack' : `hullpack[${path.basename(d)}]`;
      decoders.push({ name, stream: 's3d', decode: (b) => summary(dec.decode(b)) });
    }
  }
  if (a.only !== 'hullpack') {
    const dracoDir = path.join(repo, 'node_modules/three/examples/jsm/libs/draco');
    // A classic script defining DracoDecoderModule, then web/bench_draco.js on the same global.
    new Function(`${fs.readFileSync(path.join(dracoDir, 'draco_wasm_wrapper.js'), 'utf8')}\nself.DracoDecoderModule = DracoDecoderModule;`)();
    new Function(fs.readFileSync(path.join(repo, 'web/bench_draco.js'), 'utf8'))();
    const D = await self.hullpackBenchDracoModule(fs.readFileSync(path.join(dracoDir, 'draco_decoder.wasm')));
    decoders.push({ name: 'draco', stream: 'drc', decode: (b) => summary(self.hullpackBenchDracoDecode(D, b)) });
  }
  return decoders;
}
