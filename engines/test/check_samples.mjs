// Asserts that a driver result for make_scene.mjs's scene shows what the scene must show:
//   node engines/test/check_samples.mjs JOB.json        (exit 0 when all checks pass, 1 otherwise)
// World points are projected to pixels with three.js's own camera math (same camera as the page).
//   - ground under the box, on the sun ray through the box's centre: shadowed (factor < 0.5)
//   - open ground away from everything: lit (factor > 0.5), N.L = the ground's
//   - the top row centre (sky beyond the 40 m ground): coverage 0
//   - the fence's opaque cells draw the fence (N.L of its +Z normal); through its alpha-tested holes
//     the ground behind shows (N.L of +Y): alphaTest discards before the hook writes
//   - ground in the shadow of an opaque fence cell is shadowed, in the sun through a hole lit:
//     the shadow pass honours alphaTest too
//   - every covered pixel has a finite factor in [0, 1] and a cascade in [-1, cascades)

import fs from 'node:fs';
import path from 'node:path';
import * as THREE from 'three';
import { SUN, BOX, FENCE, fenceCellOpaque } from './make_scene.mjs';

const jobFile = path.resolve(process.argv[2] || '');
const job = JSON.parse(fs.readFileSync(jobFile, 'utf8'));
const out = path.resolve(path.dirname(jobFile), job.out);
const meta = JSON.parse(fs.readFileSync(path.join(out, 'engine.json'), 'utf8'));
const buf = fs.readFileSync(path.join(out, 'samples.f32'));
const { width: W, height: H } = job;
let failures = 0;
const check = (ok, what) => {
  process.stdout.write(`${ok ? 'ok  ' : 'FAIL'} ${what}\n`);
  if (!ok) failures++;
};

check(buf.length === W * H * 16, `samples.f32 holds ${W}x${H} RGBA float32 (${buf.length} bytes)`);
const f = new Float32Array(buf.buffer.slice(buf.byteOffset, buf.byteOffset + buf.length));
const at = (x, y) => {
  const i = (y * W + x) * 4;
  return { s: f[i], c: f[i + 1], ndl: f[i + 2], cov: f[i + 3] };
};

const cam = new THREE.PerspectiveCamera(job.camera.fovY, W / H, job.camera.near, job.camera.far);
cam.position.fromArray(job.camera.position);
cam.lookAt(new THREE.Vector3().fromArray(job.camera.target));
cam.updateMatrixWorld(true);
const pixel = (p) => {
  const v = new THREE.Vector3(...p).project(cam);
  return [Math.floor((v.x * 0.5 + 0.5) * W), Math.floor((1 - (v.y * 0.5 + 0.5)) * H)];
};
const fmt = (v) => `factor ${v.s.toFixed(3)} cascade ${v.c} N.L ${v.ndl.toFixed(3)} coverage ${v.cov}`;

const sun = new THREE.Vector3(...SUN).normalize();
const toSun = sun.clone().negate();
const groundNdl = toSun.y;
const fenceNdl = toSun.z;

// ground point on the sun ray through a world point
const groundHit = (p) => {
  const t = -p[1] / sun.y;
  return [p[0] + t * sun.x, 0, p[2] + t * sun.z];
};

{
  const g = groundHit(BOX.center);
  const [x, y] = pixel(g);
  const v = at(x, y);
  check(v.cov === 1 && v.s < 0.5 && Math.abs(v.ndl - groundNdl) < 0.02, `ground under the box (${g.map((a) => a.toFixed(2))}) at pixel ${x},${y} is shadowed: ${fmt(v)}`);
  check(v.c >= 0 && v.c < meta.cascades.length, `a cascade is picked under the box: ${v.c}`);
}
{
  const [x, y] = pixel([6, 0, 6]);
  const v = at(x, y);
  check(v.cov === 1 && v.s > 0.5 && Math.abs(v.ndl - groundNdl) < 0.02, `open ground (6, 0, 6) at pixel ${x},${y} is lit: ${fmt(v)}`);
}
{
  const v = at(W >> 1, 0);
  check(v.cov === 0, `the background (pixel ${W >> 1},0) has coverage 0: ${fmt(v)}`);
  const c = at(0, 0);
  check(c.cov === 0, `the corner (0,0) has coverage 0: ${fmt(c)}`);
}

// fence cells: centre of cell (i, j), i along +x, j down from the top
const n = FENCE.cells;
const cw = (FENCE.x1 - FENCE.x0) / n;
const ch = (FENCE.y1 - FENCE.y0) / n;
let cellsSeen = 0;
let shadowCells = 0;
for (let j = 0; j < n; j++) {
  for (let i = 0; i < n; i++) {
    const centre = [FENCE.x0 + (i + 0.5) * cw, FENCE.y1 - (j + 0.5) * ch, FENCE.z];
    const [x, y] = pixel(centre);
    const v = at(x, y);
    const opaque = fenceCellOpaque(i, j);
    const want = opaque ? fenceNdl : groundNdl;
    cellsSeen++;
    check(v.cov === 1 && Math.abs(v.ndl - want) < 0.02,
      `fence cell ${i},${j} (${opaque ? 'opaque' : 'hole'}) at pixel ${x},${y} shows ${opaque ? 'the fence' : 'the ground behind'}: ${fmt(v)}`);
    // its shadow on the ground, at the cell centre's sun ray (cells in the top row only: their
    // shadows land farthest from the fence and are the largest on screen)
    if (j < 2) {
      const g = groundHit(centre);
      const [gx, gy] = pixel(g);
      const gv = at(gx, gy);
      const isGround = Math.abs(gv.ndl - groundNdl) < 0.02;
      if (!isGround) continue; // hidden behind the fence itself
      shadowCells++;
      check(opaque ? gv.s < 0.5 : gv.s > 0.5,
        `ground in the sun ray of fence cell ${i},${j} (${opaque ? 'opaque: shadowed' : 'hole: lit'}) at pixel ${gx},${gy}: ${fmt(gv)}`);
    }
  }
}
check(shadowCells >= 4, `at least 4 fence-cell shadows were visible to check (${shadowCells})`);

// global sanity
let bad = 0;
let covered = 0;
for (let i = 0; i < W * H; i++) {
  const s = f[i * 4];
  const c = f[i * 4 + 1];
  const cov = f[i * 4 + 3];
  if (cov !== 0 && cov !== 1) bad++;
  if (cov === 1) {
    covered++;
    if (!Number.isFinite(s) || s < -1e-6 || s > 1 + 1e-6 || !Number.isInteger(c) || c < -1 || c >= meta.cascades.length) bad++;
  }
}
check(bad === 0, `every pixel: coverage 0 or 1; covered pixels have factor in [0,1] and cascade in [-1, ${meta.cascades.length}) (${bad} bad of ${covered} covered)`);
check(typeof meta.version === 'string' && meta.timings && meta.timings.totalMs > 0, `engine.json has version ${meta.version} and timings ${JSON.stringify(meta.timings)}`);

if (failures) {
  process.stdout.write(`${failures} check(s) failed (result: ${out})\n`);
  process.exit(1);
}
process.stdout.write('all checks passed\n');
