// bench_instructions.mjs: instructions per decode (valgrind --tool=callgrind, deterministic, so the
// machine's load does not disturb it) of hullpack's wasm decoder and Draco's WASM decoder in Node's
// V8 (TurboFan only, as bench_cpu.mjs runs them), and of the native C++ decoder.
//
//   node tests/web/bench_instructions.mjs [--meshes igea,bunny] [--decodes 3]
//        [--wasm DIR[,DIR2]] [--native build/tests/web/web_decode_ref] [stream options of bench.mjs]
//
// Each decoder runs in its own process under callgrind twice, decoding the stream once and
// 1 + decodes times; the difference over `decodes` is one decode's instructions, without start-up,
// compilation and the first decode's warm-up. Instructions are not time (a mispredicted branch or
// a cache miss costs many), but they compare builds of one decoder exactly and show where a wasm
// build spends more than native code; bench.mjs and bench_cpu.mjs give the times.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { nodeDecoders, parseArgs, prepareStreams } from './bench_streams.mjs';

const a = parseArgs(process.argv);

if (a.child) {
  // Child: --child NAME --stream FILE --count N (decoders of `a` as nodeDecoders builds them).
  const d = (await nodeDecoders(a)).find((x) => x.name === a.child);
  if (!d) throw new Error(`no decoder ${a.child}`);
  const bytes = new Uint8Array(fs.readFileSync(a.stream));
  for (let i = 0; i < Number(a.count); ++i) d.decode(bytes);
  process.exit(0);
}

// Instructions callgrind counts for one command.
function count(cmd, args) {
  const r = spawnSync('valgrind', ['--tool=callgrind', '--callgrind-out-file=/dev/null', cmd, ...args],
    { encoding: 'utf8', stdio: ['ignore', 'ignore', 'pipe'], maxBuffer: 1 << 26 });
  const m = /Collected : (\d+)/.exec(r.stderr || '');
  if (r.status !== 0 || !m) throw new Error(`valgrind ${cmd} ${args.join(' ')} failed: ${r.error || r.stderr}`);
  return Number(m[1]);
}

const decodes = Number(a.decodes || 3);
const script = fileURLToPath(import.meta.url);
// The same stream and wasm options reach the children.
const passOn = ['wasm'].filter((k) => a[k]).flatMap((k) => [`--${k}`, a[k]]);
const names = (await nodeDecoders(a)).map((d) => ({ name: d.name, stream: d.stream }));
const { dir, list } = prepareStreams(a);
console.log(`node ${process.version} (V8 ${process.versions.v8}); instructions per decode, millions ` +
  `(callgrind: (1 + ${decodes} decodes - 1 decode) / ${decodes})`);
console.log('| mesh | decoder | bytes | M instructions | / Draco |\n|---|---|---|---|---|');
try {
  for (const m of list) {
    const rows = [];
    if (a.native) {
      // web_decode_ref --time N decodes once, then N times.
      const s = path.join(dir, m.s3d);
      const n = (count(path.resolve(a.native), ['--time', String(1 + decodes), s]) - count(path.resolve(a.native), ['--time', '1', s])) / decodes;
      rows.push({ name: 'native C++', stream: 's3d', n });
    }
    for (const d of names) {
      const s = path.join(dir, m[d.stream]);
      const node = ['--single-threaded', '--no-liftoff', script, '--child', d.name, '--stream', s, ...passOn];
      node.push('--only', d.name === 'draco' ? 'draco' : 'hullpack');
      const n = (count(process.execPath, [...node, '--count', String(1 + decodes)]) - count(process.execPath, [...node, '--count', '1'])) / decodes;
      rows.push({ name: d.name, stream: d.stream, n });
    }
    const draco = rows.find((r) => r.name === 'draco')?.n;
    for (const r of rows) {
      const bytes = fs.statSync(path.join(dir, m[r.stream])).size;
      console.log(`| ${m.name} | ${r.name} | ${bytes} | ${(r.n / 1e6).toFixed(1)} | ${draco && r.name !== 'draco' ? (r.n / draco).toFixed(2) : ''} |`);
    }
  }
} finally {
  fs.rmSync(dir, { recursive: true, force: true });
}
