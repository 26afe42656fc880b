// A static HTTP server on 127.0.0.1 (random port) for one run:
//   /              the page: an empty document that loads /page.js
//   /page.js       the engine's esbuild bundle
//   /scene/<rel>   the glTF's directory (so relative buffer and texture URIs resolve)
//   /extra/<rel>   the extra glTF/glb's directory
// GET and HEAD only; paths that leave their directory are refused.

import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.json': 'application/json',
  '.gltf': 'model/gltf+json',
  '.glb': 'model/gltf-binary',
  '.bin': 'application/octet-stream',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg',
  '.webp': 'image/webp',
  '.avif': 'image/avif',
  '.gif': 'image/gif',
  '.bmp': 'image/bmp',
  '.ktx2': 'image/ktx2',
  '.ktx': 'image/ktx',
  '.dds': 'image/vnd-ms.dds',
  '.hdr': 'image/vnd.radiance',
  '.exr': 'image/x-exr',
  '.wasm': 'application/wasm',
};

const PAGE_HTML = `<!doctype html>
<html><head><meta charset="utf-8"><title>shadowtune engine</title>
<style>html,body{margin:0;background:#000}</style></head>
<body><script src="/page.js"></script></body></html>
`;

export function mimeType(file) {
  return MIME[path.extname(file).toLowerCase()] || 'application/octet-stream';
}

function sendFile(req, res, file) {
  fs.stat(file, (err, st) => {
    if (err || !st.isFile()) {
      res.writeHead(404, { 'Content-Type': 'text/plain' });
      res.end('not found\n');
      return;
    }
    res.writeHead(200, { 'Content-Type': mimeType(file), 'Content-Length': st.size, 'Cache-Control': 'no-store' });
    if (req.method === 'HEAD') {
      res.end();
      return;
    }
    const s = fs.createReadStream(file);
    s.on('error', () => res.destroy());
    s.pipe(res);
  });
}

// Maps /<prefix>/<rel> under `root`, refusing anything that escapes it.
function under(root, rel) {
  let decoded;
  try {
    decoded = decodeURIComponent(rel);
  } catch {
    return null;
  }
  const file = path.resolve(root, '.' + path.sep + decoded);
  if (file !== root && !file.startsWith(root + path.sep)) return null;
  return file;
}

// files: {bundle, gltf, extra} absolute paths (gltf/extra may be null). Resolves to
// {origin, urls: {gltf, extra}, close(), requests: [{url, status}]}.
export function startServer(files) {
  const roots = {
    scene: files.gltf ? path.dirname(files.gltf) : null,
    extra: files.extra ? path.dirname(files.extra) : null,
  };
  const failed = [];
  const server = http.createServer((req, res) => {
    res.on('finish', () => {
      if (res.statusCode >= 400) failed.push(`${res.statusCode} ${req.url}`);
    });
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.writeHead(405, { Allow: 'GET, HEAD' });
      res.end();
      return;
    }
    const url = new URL(req.url, 'http://127.0.0.1');
    const p = url.pathname;
    if (p === '/' || p === '/index.html') {
      res.writeHead(200, { 'Content-Type': MIME['.html'], 'Cache-Control': 'no-store' });
      res.end(req.method === 'HEAD' ? undefined : PAGE_HTML);
      return;
    }
    if (p === '/page.js') return sendFile(req, res, files.bundle);
    if (p === '/favicon.ico') {
      res.writeHead(204);
      res.end();
      return;
    }
    const m = /^\/(scene|extra)\/(.+)$/.exec(p);
    const file = m && roots[m[1]] ? under(roots[m[1]], m[2]) : null;
    if (file === null) {
      res.writeHead(404, { 'Content-Type': 'text/plain' });
      res.end('not found\n');
      return;
    }
    sendFile(req, res, file);
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const origin = `http://127.0.0.1:${server.address().port}`;
      const enc = (f) => encodeURIComponent(path.basename(f));
      resolve({
        origin,
        urls: {
          page: `${origin}/`,
          gltf: files.gltf ? `${origin}/scene/${enc(files.gltf)}` : null,
          extra: files.extra ? `${origin}/extra/${enc(files.extra)}` : null,
        },
        failed,
        close: () => new Promise((r) => {
          server.closeAllConnections?.();
          server.close(() => r());
        }),
      });
    });
  });
}
