// bench.mjs: in-browser decode time of hullpack's WASM decoder against Draco's WASM decoder, per
// mesh, on the main thread and in a Web Worker (web/bench.html in headless Chromium).
//
//   node tests/web/bench.mjs [--corpus DIR] [--meshes igea,bunny] [--runs 11] [--warmup 3]
//        [--encoder build/tools/test_o3dgc/test_o3dgc] [--qp 14 --qn 10 --qt 12] [--cl 7] [--fast 1]
//        [--wasm samples/web/dist/hullpack_decoder_wasm.wasm[,other.wasm]] [--json out.json]
//
// Every .obj of the corpus is encoded twice from the same file (bench_streams.mjs): this build's
// test_o3dgc and Debian's draco_encoder at the same qp/qn/qt bits, Draco at -cl (7 = its default).
// The page then decodes both streams with runs interleaved and prints medians. --cold N: instead,
// the first two decodes of the first mesh in N fresh browsers. --wasm compares several builds of
// the hullpack decoder in one run. Not part of ctest: on a shared machine times are a measurement,
// not a check (bench_cpu.mjs gives CPU times, which the machine's load disturbs far less).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { startServer } from './static_server.mjs';
import { fmt as f, median, parseArgs, prepareStreams, repo } from './bench_streams.mjs';

const a = parseArgs(process.argv);
const { dir, list, settings } = prepareStreams(a);
fs.writeFileSync(path.join(dir, 'list.json'), JSON.stringify(list.map((m) => ({
  name: m.name, s3d: `/__bench/${m.s3d}`, drc: `/__bench/${m.drc}` }))));

const wasm = (a.wasm || 'samples/web/dist/hullpack_decoder_wasm.wasm').split(',')
  .map((w) => `/${path.relative(repo, path.resolve(repo, w)).split(path.sep).join('/')}`);
const { server, url } = await startServer({ root: repo, mounts: { '/__bench/': dir } });
// One fresh browser (own profile, own processes) per page load.
async function runPage(query) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'hullpack-chromium-'));
  const ctx = await chromium.launchPersistentContext(profile, {
    executablePath: a.chromium || '/usr/bin/chromium', headless: true, timeout: 60000,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  try {
    const page = ctx.pages()[0] || await ctx.newPage();
    page.setDefaultTimeout(3600000);
    page.on('pageerror', (e) => console.error(`page error: ${e}`));
    await page.goto(`${url}/web/bench.html?list=/__bench/list.json&wasm=${wasm.map(encodeURIComponent).join(',')}&${query}`);
    return await page.evaluate(() => window.benchResult);
  } finally {
    await ctx.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
}

let result;
try {
  if (a.cold) {
    // --cold N: N fresh browsers, each timing the first two decodes of the first mesh per decoder
    // (the starting decoder rotates).
    const samples = {};
    for (let i = 0; i < Number(a.cold); ++i) {
      const r = await runPage(`cold=${i}`);
      for (const [name, v] of Object.entries(r.cold.decoders)) {
        (samples[name] ||= { first: [], second: [] }).first.push(v.first);
        samples[name].second.push(v.second);
      }
      result = { userAgent: r.userAgent, mesh: r.cold.mesh, samples };
    }
  } else {
    result = await runPage(`runs=${a.runs || 11}&warmup=${a.warmup || 3}`);
  }
} finally {
  server.close();
  fs.rmSync(dir, { recursive: true, force: true });
}
result.settings = { ...settings, wasm };
if (a.json) fs.writeFileSync(a.json, JSON.stringify(result, null, 1));

if (a.cold) {
  console.log(`${result.userAgent}\nfirst decodes of ${result.mesh} by a freshly compiled module, median of ${a.cold} browsers; ms`);
  console.log('| decoder | first decode | second decode |\n|---|---|---|');
  for (const [name, v] of Object.entries(result.samples)) console.log(`| ${name} | ${f(median(v.first))} | ${f(median(v.second))} |`);
  process.exit(0);
}

// Markdown table: one row per mesh and decoder: stream bytes, median ms (main thread, in the worker,
// worker round trip) and the ratio to Draco (< 1: faster than Draco).
console.log(`${result.userAgent}\nmedian of ${result.runs} runs after ${result.warmup} warm-up; ms, decode only` +
  `${settings.fastDecode ? '; hullpack streams encoded with -fast' : ''}`);
console.log(`init (fetch + compile + instantiate): ${Object.entries(result.init).map(([k, v]) => `${k} ${v.toFixed(0)} ms`).join(', ')}`);
console.log('| mesh | triangles | decoder | attributes | bytes | main ms | worker ms | worker round trip ms | main / Draco | worker / Draco |');
console.log('|---|---|---|---|---|---|---|---|---|---|');
for (const m of result.meshes) {
  const d = m.decoders.draco;
  for (const [name, v] of Object.entries(m.decoders)) {
    const ratio = (x, y) => (d && name !== 'draco' ? (x / y).toFixed(2) : '');
    console.log(`| ${m.name} | ${v.triangles} | ${name} | ${v.attributes} | ${v.bytes} | ${f(v.main)} | ${f(v.worker)} | ${f(v.roundTrip)} | ` +
      `${ratio(v.main, d?.main)} | ${ratio(v.worker, d?.worker)} |`);
  }
}
