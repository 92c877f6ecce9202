// chromium_session.mjs: what the browser tests share: the skip checks (playwright-core, npm
// packages, Debian's /usr/bin/chromium) and a headless Chromium over the local static server
// (tests/web/static_server.mjs) that reaches nothing but that server.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { startServer } from './static_server.mjs';

export const SKIP = 77;

// playwright-core; exits with SKIP when it, one of `packages` (under repo/node_modules) or
// chromium is missing.
export async function requirePlaywright({ chromiumPath, repo, packages = [] }) {
  let playwright;
  try {
    playwright = await import('playwright-core');
  } catch {
    console.log('SKIP: playwright-core is not installed (npm ci at the repository root)');
    process.exit(SKIP);
  }
  for (const pkg of packages) {
    if (!fs.existsSync(path.join(repo, 'node_modules', pkg))) {
      console.log(`SKIP: npm package ${pkg} is not installed (npm ci at the repository root)`);
      process.exit(SKIP);
    }
  }
  if (!fs.existsSync(chromiumPath)) {
    console.log(`SKIP: ${chromiumPath} not found (apt-get install chromium)`);
    process.exit(SKIP);
  }
  return playwright;
}

// Serves `repo` at / and `work` at /__work/, makes a throw-away Chromium profile and arms a
// watchdog that fails the test ("FAIL: <what> timed out") after `timeoutMs`. Then
// session.launch() starts Chromium (requests outside the server are aborted and listed in
// session.outside) and returns its first page; session.close() undoes everything.
export async function startSession({ playwright, chromiumPath, repo, work, profilePrefix, what, timeoutMs }) {
  const { server, url } = await startServer({ root: repo, mounts: { '/__work/': work } });
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), profilePrefix));
  const watchdog = setTimeout(() => {
    console.log(`FAIL: ${what} timed out`);
    process.exit(1);
  }, timeoutMs);
  const session = {
    url,
    context: undefined,
    outside: [],
    async launch({ extraArgs = [], viewport } = {}) {
      session.context = await playwright.chromium.launchPersistentContext(profile, {
        executablePath: chromiumPath,
        headless: true,
        args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
          '--disable-background-networking', '--disable-component-update', '--disable-sync', ...extraArgs],
        ...(viewport ? { viewport } : {}),
        timeout: 60000,
      });
      await session.context.route(
        (u) => !u.href.startsWith(url) && !u.href.startsWith('data:') && !u.href.startsWith('blob:'),
        (route) => { session.outside.push(route.request().url()); route.abort(); });
      return session.context.pages()[0] || await session.context.newPage();
    },
    async close() {
      clearTimeout(watchdog);
      if (session.context) await session.context.close().catch(() => {});
      server.close();
      fs.rmSync(profile, { recursive: true, force: true });
    },
  };
  return session;
}
