// bench_cpu.mjs: the decode benchmark of bench.mjs in Node instead of a browser (the same V8 and
// wasm), timed in CPU time of the process (process.cpuUsage) rather than wall time, so that other
// work on a shared machine disturbs it far less. Node runs single-threaded (V8's background
// compilation and GC on the timed thread) with TurboFan only, so every timed run is optimized code.
//
//   node --single-threaded --no-liftoff tests/web/bench_cpu.mjs [--meshes igea] [--runs 15]
//        [--warmup 3] [--wasm DIR[,DIR2]] [--native build/tests/web/web_decode_ref]
//        [same stream options as bench.mjs]
//
// --native adds the C++ decoder of that build (web_decode_ref --time: median CPU time of as many
// decodes in its own process), the reference for what the wasm build costs over native code.
// --wasm: folders holding hullpack_decoder_wasm.{js,wasm} (default samples/web/dist). Draco is
// three's copy of its official WASM decoder, driven by web/bench_draco.js as in the browser.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fmt as f, median, nodeDecoders, parseArgs, prepareStreams } from './bench_streams.mjs';

const a = parseArgs(process.argv);
const runs = Number(a.runs || 15);
const warmup = Number(a.warmup || 3);
const decoders = await nodeDecoders(a);

const { dir, list, settings } = prepareStreams(a);
console.log(`node ${process.version} (V8 ${process.versions.v8}); CPU ms per decode, median of ${runs} after ${warmup} warm-up, runs interleaved` +
  `${settings.fastDecode ? '; hullpack streams encoded with -fast' : ''}`);
console.log('| mesh | triangles | decoder | attributes | bytes | CPU ms | wall ms | CPU / Draco |\n|---|---|---|---|---|---|---|---|');
try {
  for (const m of list) {
    const bytes = { s3d: new Uint8Array(fs.readFileSync(path.join(dir, m.s3d))), drc: new Uint8Array(fs.readFileSync(path.join(dir, m.drc))) };
    const rows = decoders.map((d) => ({ d, counts: d.decode(bytes[d.stream]), cpu: [], wall: [] }));
    for (let i = 0; i < warmup; ++i) for (const r of rows) r.d.decode(bytes[r.d.stream]);
    for (let k = 0; k < runs; ++k) {
      for (let j = 0; j < rows.length; ++j) {
        const r = rows[(j + k) % rows.length];
        const c0 = process.cpuUsage();
        const t0 = performance.now();
        r.d.decode(bytes[r.d.stream]);
        const c = process.cpuUsage(c0);
        r.wall.push(performance.now() - t0);
        r.cpu.push((c.user + c.system) / 1000);
      }
    }
    const draco = median(rows[rows.length - 1].cpu);
    if (a.native) {
      const r = JSON.parse(execFileSync(path.resolve(a.native), ['--time', String(runs), path.join(dir, m.s3d)], { encoding: 'utf8' }));
      console.log(`| ${m.name} | ${rows[0].counts[1]} | native C++ | ${rows[0].counts[2]} | ${bytes.s3d.length} | ${f(r.cpu_ms)} | | ${(r.cpu_ms / draco).toFixed(2)} |`);
    }
    for (const r of rows) {
      const cpu = median(r.cpu);
      console.log(`| ${m.name} | ${r.counts[1]} | ${r.d.name} | ${r.counts[2]} | ${bytes[r.d.stream].length} | ${f(cpu)} | ${f(median(r.wall))} | ` +
        `${r.d.name === 'draco' ? '' : (cpu / draco).toFixed(2)} |`);
    }
  }
} finally {
  fs.rmSync(dir, { recursive: true, force: true });
}
