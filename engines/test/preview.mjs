// Writes a PNG preview of a driver result:
//   node engines/test/preview.mjs OUTDIR [PNG [PANELS]]   (default PNG: OUTDIR/preview.png)
// PANELS: a subset of "fcn" in any order (default "fcn"); side by side, each width x height:
//   1. shadow factor, grey 0..1 (background dark blue, factor > 1 or < 0 in red)
//   2. cascade: 0 red, 1 green, 2 blue, 3 yellow, 4 magenta, 5 cyan, ... (-1 white), shaded by the factor
//   3. N.L, grey 0..1 (negative in dark purple)

import fs from 'node:fs';
import path from 'node:path';
import { encodePNG } from './png.mjs';

const CASCADE_COLOURS = [[230, 60, 60], [60, 200, 80], [70, 110, 240], [230, 210, 60], [210, 80, 210], [70, 210, 220], [240, 150, 60], [150, 150, 150]];

export function preview(outDir, pngFile, panels = 'fcn') {
  const meta = JSON.parse(fs.readFileSync(path.join(outDir, 'engine.json'), 'utf8'));
  const { width: w, height: h } = meta;
  const buf = fs.readFileSync(path.join(outDir, 'samples.f32'));
  const f = new Float32Array(buf.buffer, buf.byteOffset, buf.length / 4);
  const order = [...panels].map((p) => 'fcn'.indexOf(p));
  if (!order.length || order.some((k) => k < 0)) throw new Error(`panels must be letters of "fcn", got ${JSON.stringify(panels)}`);
  const W = w * order.length;
  const px = new Uint8Array(W * h * 4);
  const put = (x, y, r, g, b) => {
    const k = order.indexOf(Math.floor(x / w));
    if (k < 0) return;
    x = (x % w) + k * w;
    const o = (y * W + x) * 4;
    px[o] = r;
    px[o + 1] = g;
    px[o + 2] = b;
    px[o + 3] = 255;
  };
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const i = (y * w + x) * 4;
      const [s, c, ndl, cov] = [f[i], f[i + 1], f[i + 2], f[i + 3]];
      if (!(cov > 0.5)) {
        put(x, y, 20, 30, 70);
        put(x + w, y, 20, 30, 70);
        put(x + 2 * w, y, 20, 30, 70);
        continue;
      }
      if (s > 1.001 || s < -0.001 || Number.isNaN(s)) put(x, y, 255, 0, 0);
      else {
        const g = Math.round(255 * s);
        put(x, y, g, g, g);
      }
      const k = 0.35 + 0.65 * Math.min(Math.max(s, 0), 1);
      const col = c < -0.5 ? [255, 255, 255] : CASCADE_COLOURS[Math.round(c) % CASCADE_COLOURS.length];
      put(x + w, y, Math.round(col[0] * k), Math.round(col[1] * k), Math.round(col[2] * k));
      if (ndl < 0) put(x + 2 * w, y, 60, 20, 60);
      else {
        const g = Math.round(255 * Math.min(ndl, 1));
        put(x + 2 * w, y, g, g, g);
      }
    }
  }
  fs.writeFileSync(pngFile, encodePNG(W, h, px));
}

if (import.meta.url === `file://${process.argv[1]}`) {
  if (process.argv.length < 3) {
    process.stderr.write('usage: node preview.mjs OUTDIR [PNG]\n');
    process.exit(2);
  }
  const out = path.resolve(process.argv[2]);
  const png = process.argv[3] ? path.resolve(process.argv[3]) : path.join(out, 'preview.png');
  preview(out, png, process.argv[4] || 'fcn');
  process.stdout.write(png + '\n');
}
