// engines_test.mjs: the drop tests in real engines, in headless Chromium (playwright-core + Debian's
// /usr/bin/chromium), against the native Bullet reference (web_bullet_drop):
//   node tests/web/engines_test.mjs --repo DIR --work DIR
// --work holds omi.glb and khr.glb (`hullpack pack` of the torus, both collider forms), khr.ref.glb
// (`hullpack unpack`) and omi.bullet.json / khr.bullet.json (web_bullet_drop). Every engine must
// bring the torus to rest within 1 % of its height of Bullet's resting height, and be given exactly
// the hull points the C++ reader reads. Nothing is fetched but the local server (node_modules).
// Exit 0 pass, 1 fail, 77 skip.
import fs from 'node:fs';
import path from 'node:path';
import { requirePlaywright, startSession } from './chromium_session.mjs';

const a = {};
for (let i = 2; i + 1 < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
if (!a.repo || !a.work) {
  console.error('usage: node engines_test.mjs --repo DIR --work DIR [--chromium PATH]');
  process.exit(64);
}
const repo = path.resolve(a.repo);
const work = path.resolve(a.work);
const chromiumPath = a.chromium || '/usr/bin/chromium';

let failures = 0;
function check(cond, what) {
  console.log(`${cond ? 'ok  ' : 'FAIL'} ${what}`);
  if (!cond) failures += 1;
}

const playwright = await requirePlaywright({
  chromiumPath,
  repo,
  packages: ['three', '@babylonjs/core', '@babylonjs/loaders', '@babylonjs/havok', '@dimforge/rapier3d-compat'],
});

// Same points: every hull, every coordinate, as float32 (the C++ reader prints 9 digits).
function samePoints(engine, native) {
  if (engine.length !== native.length) return `${engine.length} hulls != C++ ${native.length}`;
  for (let h = 0; h < engine.length; ++h) {
    const e = Float32Array.from(engine[h]);
    const n = Float32Array.from(native[h]);
    if (e.length !== n.length) return `hull ${h}: ${e.length / 3} points != C++ ${n.length / 3}`;
    for (let i = 0; i < e.length; ++i) if (e[i] !== n[i]) return `hull ${h} value ${i}: ${e[i]} != C++ ${n[i]}`;
  }
  return '';
}

const session = await startSession({
  playwright, chromiumPath, repo, work, profilePrefix: 'hullpack-engines-', what: 'engine test', timeoutMs: 200000,
});
const { url, outside } = session;
try {
  const page = await session.launch();
  page.setDefaultTimeout(120000);
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(`${url}/tests/web/engines.html`);
  await page.waitForFunction(() => window.engineTestsReady === true);

  const runs = [
    ['three.js + Rapier (OMI hulls)', 'omi', 'threeRapier'],
    ['Babylon.js + Havok (KHR_physics hulls)', 'khr', 'babylonHavok'],
  ];
  for (const [name, form, fn] of runs) {
    const bullet = JSON.parse(fs.readFileSync(path.join(work, `${form}.bullet.json`), 'utf8'));
    const got = await page.evaluate(([f, glb, ref]) => window.engineTests[f](glb, ref),
      [fn, `/__work/${form}.glb`, `/__work/${form}.ref.glb`]);
    const off = Math.abs(got.restZ - bullet.restZ);
    console.log(`${name}: rests at z ${got.restZ.toFixed(5)}, Bullet ${bullet.restZ.toFixed(5)}, ` +
      `off by ${(100 * off / bullet.height).toFixed(3)} % of the height ${bullet.height.toFixed(4)}`);
    check(off <= 0.01 * bullet.height, `${name}: rests within 1 % of its height of Bullet's resting height`);
    check(got.speed < 0.01, `${name}: at rest (speed ${got.speed.toExponential(2)})`);
    check(got.vertices > 0, `${name}: the render mesh decoded (${got.vertices} vertices)`);
    const diff = samePoints(got.points, bullet.hulls);
    check(diff === '', `${name}: the engine is given the C++ reader's hull points${diff ? `: ${diff}` : ''}`);
    if (got.engineVertices) {
      // Rapier's own hull: every vertex it kept is one of the file's points.
      const ok = got.engineVertices.every((vs, h) => {
        const pts = new Set();
        for (let i = 0; i < bullet.hulls[h].length; i += 3) pts.add(Float32Array.from(bullet.hulls[h].slice(i, i + 3)).join());
        for (let i = 0; i < vs.length; i += 3) if (!pts.has(Float32Array.from(vs.slice(i, i + 3)).join())) return false;
        return vs.length >= 12;
      });
      check(ok, `${name}: every vertex of the engine's convex hulls is a C++ reader's point`);
    }
    if (got.samePositions !== undefined) {
      check(got.samePositions, `${name}: Babylon's decoded render positions == C++ reader's, value for value`);
    }
  }
  // Babylon's readCollisionHulls on the earlier hull form (streams; make_glb.mjs), against the C++
  // reader (earlier.bullet.json).
  const earlierRef = JSON.parse(fs.readFileSync(path.join(work, 'earlier.bullet.json'), 'utf8'));
  const earlier = await page.evaluate((glb) => window.engineTests.babylonEarlierHulls(glb), '/__work/earlier.glb');
  const earlierDiff = samePoints(earlier.points, earlierRef.hulls);
  check(earlierDiff === '' && earlier.points.length > 0,
    `Babylon readCollisionHulls, earlier form (${earlier.points.length} hull streams): the C++ reader's points${earlierDiff ? `: ${earlierDiff}` : ''}`);
  check(/pass a decoder/.test(earlier.withoutDecoder),
    `Babylon readCollisionHulls, earlier form without a decoder: a clear error (${earlier.withoutDecoder})`);
  // The animated character: its four clips reach both engines, and three.js plays them. Its key
  // frames are stored with EXT_meshopt_compression, which both engines decode.
  const characterJson = (() => {
    const glb = fs.readFileSync(path.join(work, 'character.glb'));
    return JSON.parse(glb.subarray(20, 20 + glb.readUInt32LE(12)).toString('utf8'));
  })();
  check((characterJson.extensionsRequired || []).includes('EXT_meshopt_compression'),
    `the packed character's key frames are compressed (extensionsRequired: ${characterJson.extensionsRequired})`);
  const clips = await page.evaluate((glb) => window.engineTests.animatedClips(glb), '/__work/character.glb');
  check(clips.threeClips.length === 4, `three.js sees the character's 4 clips (${clips.threeClips.join(', ')})`);
  check(clips.babylonClips.length === 4, `Babylon sees the character's 4 clips (${clips.babylonClips.join(', ')})`);
  check(clips.turned > 1e-3, `three.js plays a clip: a node it rotates turns by ${clips.turned.toFixed(4)} rad in 0.3 s`);
  // Morph targets: both engines get the decoded offsets (inflate: 0.25 out, within the packing
  // error), the names, and three.js plays the weights clip.
  const morph = await page.evaluate((glb) => window.engineTests.morphTargets(glb), '/__work/morph.glb');
  const near = (x, y) => Math.abs(x - y) < 0.01;
  check(morph.threeNames.join() === 'inflate,squash' && near(morph.threeOffsets[0], 0.25),
    `three.js sees the morph targets ${morph.threeNames.join(', ')}, inflate moving ${morph.threeOffsets[0]?.toFixed(4)} (0.25)`);
  check(near(morph.threeWeightAt1s, 1), `three.js plays the weights clip: inflate ${morph.threeWeightAt1s.toFixed(4)} at 1 s (1)`);
  check(morph.babylonNames.join() === 'inflate,squash' && near(morph.babylonOffsets[0], 0.25) &&
        morph.babylonClips.join() === 'breathe',
  `Babylon sees the morph targets ${morph.babylonNames.join(', ')}, inflate moving ${morph.babylonOffsets[0]?.toFixed(4)} (0.25), clips ${morph.babylonClips.join(', ')}`);
  check(outside.length === 0, `nothing fetched from outside the local server${outside.length ? `: ${outside.join(' ')}` : ''}`);
  check(errors.length === 0, `no page errors${errors.length ? `: ${errors.join(' | ')}` : ''}`);
} catch (e) {
  console.log(`FAIL: ${e && e.stack ? e.stack : e}`);
  failures += 1;
} finally {
  await session.close();
}
console.log(failures ? `${failures} check(s) failed` : 'all engine checks passed');
process.exit(failures ? 1 : 0);
