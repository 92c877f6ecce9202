// static_server.mjs: a tiny static file server on 127.0.0.1 for the viewer and the browser test.
//   node tests/web/static_server.mjs [port]    serves the repository; open
//   http://127.0.0.1:<port>/samples/web/index.html
// startServer({root, mounts: {'/__work/': dir}, port: 0}) -> {server, port, url}
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.json': 'application/json', '.wasm': 'application/wasm', '.glb': 'model/gltf-binary', '.png': 'image/png',
  '.css': 'text/css', '.s3d': 'application/octet-stream', '.bin': 'application/octet-stream',
};

export function startServer({ root, mounts = {}, port = 0 }) {
  const resolveFile = (urlPath) => {
    let base = root;
    let rel = urlPath;
    for (const [prefix, dir] of Object.entries(mounts)) {
      if (urlPath.startsWith(prefix)) {
        base = dir;
        rel = urlPath.slice(prefix.length);
        break;
      }
    }
    const file = path.resolve(base, `.${path.posix.normalize(`/${rel}`)}`);
    return file === base || file.startsWith(base + path.sep) ? file : null;
  };
  const server = http.createServer((req, res) => {
    let urlPath;
    try {
      urlPath = decodeURIComponent(new URL(req.url, 'http://127.0.0.1').pathname);
    } catch {
      res.writeHead(400).end();
      return;
    }
    const file = resolveFile(urlPath);
    if (!file || req.method !== 'GET' && req.method !== 'HEAD') {
      res.writeHead(403).end();
      return;
    }
    fs.stat(file, (err, st) => {
      if (err || !st.isFile()) {
        res.writeHead(404, { 'content-type': 'text/plain' }).end(`not found: ${urlPath}`);
        return;
      }
      res.writeHead(200, {
        'content-type': TYPES[path.extname(file)] || 'application/octet-stream',
        'content-length': st.size,
        'cache-control': 'no-store',
      });
      if (req.method === 'HEAD') res.end();
      else fs.createReadStream(file).pipe(res);
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', () => {
      const p = server.address().port;
      resolve({ server, port: p, url: `http://127.0.0.1:${p}` });
    });
  });
}

if (process.argv[1] && fileURLToPath(import.meta.url) === path.resolve(process.argv[1])) {
  const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
  const { url } = await startServer({ root, port: Number(process.argv[2] || 8080) });
  console.log(`serving ${root} at ${url}/samples/web/index.html`);
}
