// bench.mjs: in-browser decode time of hullpack's WASM decoder against Draco's WASM decoder, per
// mesh, on the main thread and in a Web Worker (web/bench.html in headless Chromium).
//
//   node tests/web/bench.mjs [--corpus DIR] [--meshes igea,bunny] [--runs 11] [--warmup 3]
//        [--encoder build/tools/test_o3dgc/test_o3dgc] [--qp 14 --qn 10 --qt 12] [--cl 7]
//        [--wasm samples/web/dist/hullpack_decoder_wasm.wasm[,other.wasm]] [--json out.json]
//
// Every .obj of the corpus (manifest.csv order when there is one) is encoded twice from the same
// file: with this build's test_o3dgc (binary stream) and with Debian's draco_encoder, both at
// qp/qn/qt bits, Draco at -cl (7 = its default). The page then decodes both streams with runs
// interleaved and prints medians. Not part of ctest (the machine's load makes times a
// measurement, not a check). --wasm compares several builds of the hullpack decoder in one run.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from './static_server.mjs';

const a = {};
for (let i = 2; i + 1 < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const corpus = path.resolve(a.corpus || path.join(repo, '../shared/corpus'));
const encoder = path.resolve(a.encoder || path.join(repo, 'build/tools/test_o3dgc/test_o3dgc'));
const bits = { qp: a.qp || '14', qn: a.qn || '10', qt: a.qt || '12' };
const cl = a.cl || '7';

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
  execFileSync(encoder, ['-c', '-st', 'binary', '-qc', bits.qp, '-qn', bits.qn, '-qt', bits.qt, '-i', obj], { stdio: 'ignore' });
  execFileSync('draco_encoder', ['-i', obj, '-o', path.join(dir, `${name}.drc`), '-qp', bits.qp, '-qn', bits.qn,
    '-qt', bits.qt, '-cl', cl], { stdio: 'ignore' });
  list.push({ name, s3d: `/__bench/${name}.s3d`, drc: `/__bench/${name}.drc` });
}
fs.writeFileSync(path.join(dir, 'list.json'), JSON.stringify(list));

const wasm = (a.wasm || 'samples/web/dist/hullpack_decoder_wasm.wasm').split(',')
  .map((w) => `/${path.relative(repo, path.resolve(repo, w)).split(path.sep).join('/')}`);
const { server, url } = await startServer({ root: repo, mounts: { '/__bench/': dir } });
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'hullpack-chromium-'));
const ctx = await chromium.launchPersistentContext(profile, {
  executablePath: a.chromium || '/usr/bin/chromium', headless: true, timeout: 60000,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
let result;
try {
  const page = ctx.pages()[0] || await ctx.newPage();
  page.setDefaultTimeout(3600000);
  page.on('pageerror', (e) => console.error(`page error: ${e}`));
  await page.goto(`${url}/web/bench.html?list=/__bench/list.json&runs=${a.runs || 11}&warmup=${a.warmup || 3}` +
    `&wasm=${wasm.map(encodeURIComponent).join(',')}`);
  result = await page.evaluate(() => window.benchResult);
} finally {
  await ctx.close();
  server.close();
  fs.rmSync(profile, { recursive: true, force: true });
  fs.rmSync(dir, { recursive: true, force: true });
}
result.settings = { ...bits, dracoCl: cl, corpus, encoder, wasm };
if (a.json) fs.writeFileSync(a.json, JSON.stringify(result, null, 1));

// Markdown table: one row per mesh and decoder: stream bytes, median ms (main thread, in the worker,
// worker round trip) and the ratio to Draco (< 1: faster than Draco).
const f = (x) => (x < 10 ? x.toFixed(2) : x.toFixed(1));
console.log(`${result.userAgent}\nmedian of ${result.runs} runs after ${result.warmup} warm-up; ms, decode only`);
console.log(`init (fetch + compile + instantiate): ${Object.entries(result.init).map(([k, v]) => `${k} ${v.toFixed(0)} ms`).join(', ')}`);
console.log('| mesh | triangles | decoder | bytes | main ms | worker ms | worker round trip ms | main / Draco | worker / Draco |');
console.log('|---|---|---|---|---|---|---|---|---|');
for (const m of result.meshes) {
  const d = m.decoders.draco;
  for (const [name, v] of Object.entries(m.decoders)) {
    const ratio = (x, y) => (d && name !== 'draco' ? (x / y).toFixed(2) : '');
    console.log(`| ${m.name} | ${v.triangles} | ${name} | ${v.bytes} | ${f(v.main)} | ${f(v.worker)} | ${f(v.roundTrip)} | ` +
      `${ratio(v.main, d?.main)} | ${ratio(v.worker, d?.worker)} |`);
  }
}
