// bench.mjs: in-browser decode time, hullpack WASM decoder vs Draco's WASM decoder (web/bench.html).
//   node tests/web/bench.mjs --s3d igea.s3d --drc igea.drc [--runs 7]
// Not part of ctest. Prints the page's JSON result.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from './static_server.mjs';

const a = {};
for (let i = 2; i + 1 < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'hullpack-bench-'));
fs.copyFileSync(a.s3d, path.join(dir, 'm.s3d'));
fs.copyFileSync(a.drc, path.join(dir, 'm.drc'));
const { server, url } = await startServer({ root: repo, mounts: { '/__bench/': dir } });
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'hullpack-chromium-'));
const ctx = await chromium.launchPersistentContext(profile, {
  executablePath: a.chromium || '/usr/bin/chromium', headless: true, timeout: 60000,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
try {
  const page = ctx.pages()[0] || await ctx.newPage();
  page.setDefaultTimeout(300000);
  await page.goto(`${url}/web/bench.html?s3d=/__bench/m.s3d&drc=/__bench/m.drc&runs=${a.runs || 7}`);
  console.log(JSON.stringify(await page.evaluate(() => window.benchResult), null, 1));
} finally {
  await ctx.close();
  server.close();
  fs.rmSync(profile, { recursive: true, force: true });
  fs.rmSync(dir, { recursive: true, force: true });
}
