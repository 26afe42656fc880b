// End-to-end checks of engines/babylon/page.js through the real driver (engines/run.mjs), and of the
// formulas of engines/babylon/NOTES.md against what Babylon computed:
//   node engines/babylon/test/check.mjs [--truck-town]     (exit 0 when every check passes)
//
//  1. box + culling scene (make_scene.mjs), bias 0.005: the box's shadow on the ground; open ground lit;
//     N.L of the ground = sin(sun elevation); background (factor 1, cascade -1, coverage 0); the
//     down-facing single-sided quad casts nothing, the up-facing one does (depth-pass culling);
//     the cascade each pixel reports = the first split >= its view depth.
//  2. marker scene: the pixels of a 0.2 m cube at world (1, 0, 0) are centred where shadowtune's GL
//     camera (glm lookAtRH + perspective) projects (1, 0, 0).
//  3. Babylon's defaults as the page reports them; the splits, light boxes and light matrices of
//     reference.mjs (written from NOTES.md) equal Babylon's.
//  4. the depth bias: the shadow of the box's top face on the ground at (2.25, 0, 0) flips between
//     bias = 0.95 and 1.05 times dz / (k * zRange) with k = 1.5 (depthClamp) and k = 0.5 (no clamp).
//  --truck-town: also 3. on /work/shared/assets/truck_town (defaults, and stabilizeCascades).
// ~10 driver runs (~40 s on 2 busy cores). ST_TEST_KEEP=1 keeps the work directory.

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { referenceCascades, castersBoxFromGltf, splits } from './reference.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const RUN = path.resolve(here, '..', '..', 'run.mjs');
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'shadowtune-babylon-check-'));
const truckTown = process.argv.includes('--truck-town');
let failures = 0;
const check = (ok, what) => {
  process.stdout.write(`${ok ? 'ok  ' : 'FAIL'} ${what}\n`);
  if (!ok) failures++;
};

spawnSync(process.execPath, [path.join(here, 'make_scene.mjs'), path.join(work, 'scenes')], { stdio: 'ignore' });
const scene = (name) => path.join(work, 'scenes', name);

function run(name, job) {
  const file = path.join(work, `${name}.json`);
  job = { engine: 'babylon', ...job, out: path.join(work, `${name}.out`) };
  fs.writeFileSync(file, JSON.stringify(job, null, 1));
  const r = spawnSync(process.execPath, [RUN, file], { encoding: 'utf8' });
  if (r.status !== 0) {
    check(false, `run.mjs ${name}: exit ${r.status}: ${r.stderr.trim()}`);
    return null;
  }
  const meta = JSON.parse(fs.readFileSync(path.join(job.out, 'engine.json'), 'utf8'));
  const b = fs.readFileSync(path.join(job.out, 'samples.f32'));
  const f = new Float32Array(b.buffer.slice(b.byteOffset, b.byteOffset + b.length));
  const at = (x, y) => {
    const i = (Math.floor(y) * job.width + Math.floor(x)) * 4;
    return { s: f[i], c: f[i + 1], ndl: f[i + 2], cov: f[i + 3] };
  };
  return { job, meta, f, at };
}

// shadowtune's GL camera: world point -> pixel (x right, y down) and view depth
const sub = (a, b) => a.map((x, i) => x - b[i]);
const dot = (a, b) => a.reduce((s, x, i) => s + x * b[i], 0);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => a.map((x) => x / Math.hypot(...a));
function project(job, p) {
  const { position: e, target: t, fovY } = job.camera;
  const f = norm(sub(t, e));
  const s = norm(cross(f, Math.abs(f[1]) > 0.9998477 ? [0, 0, 1] : [0, 1, 0]));
  const u = cross(s, f);
  const d = sub(p, e);
  const depth = dot(d, f);
  const ty = Math.tan((fovY * Math.PI) / 360);
  const ndcX = dot(d, s) / (depth * ty * (job.width / job.height));
  const ndcY = dot(d, u) / (depth * ty);
  return { x: ((ndcX + 1) / 2) * job.width, y: ((1 - ndcY) / 2) * job.height, depth };
}
const fmt = (v) => `factor ${v.s.toFixed(3)} cascade ${v.c} N.L ${v.ndl.toFixed(3)} coverage ${v.cov}`;

const d = Math.PI / 180;
const toSun = [Math.cos(30 * d) * Math.cos(220 * d), Math.sin(30 * d), Math.cos(30 * d) * Math.sin(220 * d)];
const SUN = toSun.map((x) => -x);
// ground point hit by the sun ray through p
const groundHit = (p, sun) => { const t = -p[1] / sun[1]; return [p[0] + t * sun[0], 0, p[2] + t * sun[2]]; };

// 1. box + culling
{
  const r = run('box', {
    width: 320, height: 180, scene: { gltf: scene('box.glb'), extra: scene('culling.glb') },
    camera: { position: [10, 8, 14], target: [1, 1, -1], fovY: 60, near: 0.1, far: 100 }, sun: { direction: SUN }, settings: { bias: 0.005 },
  });
  if (r) {
    const px = (p) => { const q = project(r.job, p); return { ...r.at(q.x, q.y), q }; };
    const under = px(groundHit([0, 2.5, 0], SUN));
    check(under.cov === 1 && under.s < 0.05, `ground under the box is shadowed: ${fmt(under)}`);
    const open = px([-6, 0, 8]);
    check(open.cov === 1 && open.s > 0.99 && Math.abs(open.ndl - toSun[1]) < 1e-3, `open ground is lit, N.L = sin 30 deg: ${fmt(open)}`);
    const up = px(groundHit([6.5, 2, -6], SUN));
    check(up.cov === 1 && up.s < 0.05, `the up-facing (sun-facing) single-sided quad casts: ${fmt(up)}`);
    const down = px(groundHit([6.5, 2, 0], SUN));
    check(down.cov === 1 && down.s > 0.99, `the down-facing single-sided quad casts nothing (culled in the depth pass): ${fmt(down)}`);
    const bg = r.at(160, 2);
    check(bg.cov === 0 && bg.s === 1 && bg.c === -1, `background: ${fmt(bg)}`);
    // cascade = first split >= view depth, on ground pixels
    let bad = 0;
    let n = 0;
    const cam = r.job.camera;
    const { s: S, u: U, f: F } = (() => {
      const f = norm(sub(cam.target, cam.position));
      const s = norm(cross(f, [0, 1, 0]));
      return { s, u: cross(s, f), f };
    })();
    const ty = Math.tan((cam.fovY * Math.PI) / 360);
    const splitsFar = r.meta.cascades.map((c) => c.splitFar);
    for (let y = 110; y < 180; y += 2) {
      for (let x = 0; x < 320; x += 5) {
        const v = r.at(x, y);
        if (v.cov !== 1 || Math.abs(v.ndl - toSun[1]) > 1e-3) continue; // ground only
        // ray through the pixel centre, hit y = 0
        const nx = ((x + 0.5) / 320) * 2 - 1;
        const ny = 1 - ((y + 0.5) / 180) * 2;
        const dir = [0, 1, 2].map((k) => F[k] + S[k] * nx * ty * (320 / 180) + U[k] * ny * ty);
        const t = -cam.position[1] / dir[1];
        const depth = t; // dir has unit component along F
        const want = splitsFar.findIndex((z) => z >= depth);
        const near = splitsFar.some((z) => Math.abs(z - depth) < 0.02);
        if (near) continue;
        n++;
        if (want !== v.c) bad++;
      }
    }
    check(n > 100 && bad === 0, `the reported cascade is the first split >= the pixel's view depth (${n} ground pixels, ${bad} differ)`);
    const box = castersBoxFromGltf([scene('box.glb'), scene('culling.glb')]);
    compareCascades('box', r, box);
  }
}

// 2. projection
{
  const r = run('marker', {
    width: 320, height: 180, scene: { gltf: scene('marker.glb'), extra: null },
    camera: { position: [3, 2, 6], target: [0, 0, 0], fovY: 50, near: 0.1, far: 50 }, sun: { direction: SUN }, settings: {},
  });
  if (r) {
    let sx = 0, sy = 0, n = 0;
    for (let y = 0; y < 180; y++) for (let x = 0; x < 320; x++) if (r.at(x, y).cov === 1) { sx += x + 0.5; sy += y + 0.5; n++; }
    const q = project(r.job, [1, 0, 0]);
    check(n > 20 && Math.hypot(sx / n - q.x, sy / n - q.y) < 0.5,
      `world (1,0,0): marker centroid (${(sx / n).toFixed(2)}, ${(sy / n).toFixed(2)}) vs shadowtune's camera (${q.x.toFixed(2)}, ${q.y.toFixed(2)})`);
  }
}

// 3. defaults and cascade set-up
function compareCascades(name, r, castersBox) {
  // with Babylon's own camera matrices (float32), so only the cascade code is compared
  const ref = referenceCascades(r.job, castersBox, { view: r.meta.info.camera.viewMatrix, proj: r.meta.info.camera.projectionMatrix });
  const got = r.meta.cascades;
  const rel = (a, b) => Math.max(...a.map((x, i) => Math.abs(x - b[i]) / Math.max(1, Math.abs(b[i]))));
  let worstSplit = 0, worstExt = 0, worstM = 0;
  for (let i = 0; i < ref.length; ++i) {
    worstSplit = Math.max(worstSplit, Math.abs(ref[i].splitFar - got[i].splitFar) / got[i].splitFar);
    worstExt = Math.max(worstExt, rel(ref[i].minExtents, got[i].minExtents), rel(ref[i].maxExtents, got[i].maxExtents));
    worstM = Math.max(worstM, rel(ref[i].transformMatrix, got[i].transformMatrix));
  }
  check(ref.length === got.length && worstSplit < 1e-12, `${name}: splits = reference.mjs (max rel. diff ${worstSplit.toExponential(1)})`);
  check(worstExt < 1e-5, `${name}: light boxes (x/y extents of the slice, caster-tightened z) = reference.mjs (max rel. diff ${worstExt.toExponential(1)})`);
  check(worstM < 1e-5, `${name}: light matrices incl. the texel snap = reference.mjs (max diff ${worstM.toExponential(1)})`);
}
{
  const r = run('defaults', {
    width: 160, height: 90, scene: { gltf: scene('box.glb'), extra: null },
    camera: { position: [10, 8, 14], target: [1, 1, -1], fovY: 60, near: 0.1, far: 100 }, sun: { direction: SUN }, settings: {},
  });
  if (r) {
    const g = r.meta.info.generator;
    const want = { mapSize: 1024, numCascades: 4, lambda: 0.5, shadowMaxZ: 100, stabilizeCascades: false, depthClamp: true, autoCalcDepthBounds: false,
      cascadeBlendPercentage: 0.1, freezeShadowCastersBoundingInfo: false, bias: 0.00005, normalBias: 0, filter: 'PCF', filteringQuality: 'high',
      darkness: 0, penumbraDarkness: 1, frustumEdgeFalloff: 0, contactHardeningLightSizeUVRatio: 0.1, forceBackFacesOnly: false, minDistance: 0, maxDistance: 1 };
    const diff = Object.entries(want).filter(([k, v]) => g[k] !== v);
    check(diff.length === 0, `Babylon's defaults are NOTES.md's: ${diff.length ? JSON.stringify(diff.map(([k]) => [k, g[k]])) : 'all equal'}`);
    const s = splits({ near: 0.1, far: 100 });
    check(s.every((x, i) => x.splitFar === r.meta.cascades[i].splitFar), `splits of near 0.1, far 100, lambda 0.5: ${s.map((x) => x.splitFar.toFixed(3)).join(', ')}`);
  }
  const st = run('stabilized', {
    width: 160, height: 90, scene: { gltf: scene('box.glb'), extra: scene('culling.glb') },
    camera: { position: [10, 8, 14], target: [1, 1, -1], fovY: 60, near: 0.1, far: 100 }, sun: { direction: SUN },
    settings: { stabilizeCascades: true, numCascades: 3, lambda: 0.8, depthClamp: false, mapSize: 512 },
  });
  if (st) compareCascades('stabilized, 3 cascades, no depth clamp', st, castersBoxFromGltf([scene('box.glb'), scene('culling.glb')]));
}

// 4. the bias: box top face (y = 3.5) shadows ground (2.25, 0, 0) under sun (1, -2, 0)/sqrt 5
{
  const sun = [1 / Math.sqrt(5), -2 / Math.sqrt(5), 0];
  const dz = 3.5 / (2 / Math.sqrt(5)); // light-space distance from the top face to the ground point
  const base = {
    width: 160, height: 90, scene: { gltf: scene('box.glb'), extra: null },
    camera: { position: [9, 5, 0.01], target: [2, 0, 0], fovY: 40, near: 0.5, far: 30 }, sun: { direction: sun },
  };
  for (const [clamp, k] of [[true, 1.5], [false, 0.5]]) {
    const probe = run(`bias-probe-${clamp}`, { ...base, settings: { filteringQuality: 'low', depthClamp: clamp, bias: 0 } });
    if (!probe) continue;
    const q = project(probe.job, [2.25, 0, 0]);
    const c = probe.meta.cascades[probe.at(q.x, q.y).c];
    const zRange = c.maxExtents[2] - c.minExtents[2];
    const bStar = dz / (k * zRange);
    const lo = run(`bias-lo-${clamp}`, { ...base, settings: { filteringQuality: 'low', depthClamp: clamp, bias: 0.95 * bStar } });
    const hi = run(`bias-hi-${clamp}`, { ...base, settings: { filteringQuality: 'low', depthClamp: clamp, bias: 1.05 * bStar } });
    if (!lo || !hi) continue;
    const a = lo.at(q.x, q.y);
    const b = hi.at(q.x, q.y);
    check(a.s === 0 && b.s === 1,
      `depthClamp ${clamp}: stored depth = z01 + ${k} * bias: ground at (2.25,0,0) shadowed at bias ${(0.95 * bStar).toFixed(4)} (${a.s}), lit at ${(1.05 * bStar).toFixed(4)} (${b.s}) [dz ${dz.toFixed(3)} m, z range ${zRange.toFixed(3)} m]`);
  }
}

if (truckTown) {
  const gltf = '/work/shared/assets/truck_town/truck_town.gltf';
  const box = castersBoxFromGltf([gltf]);
  for (const [name, settings] of [['truck-town', {}], ['truck-town-stable', { stabilizeCascades: true, mapSize: 2048, lambda: 0.9, shadowMaxZ: 300 }]]) {
    const r = run(name, {
      width: 320, height: 180, scene: { gltf, extra: null },
      camera: { position: [40, 14, 45], target: [0, 2, 0], fovY: 60, near: 0.3, far: 1500 }, sun: { direction: SUN }, settings,
    });
    if (r) {
      const cb = r.meta.info.generator.castersBoxWorld;
      const e = Math.max(...[0, 1, 2].map((k) => Math.max(Math.abs(cb.min[k] - box.min[k]), Math.abs(cb.max[k] - box.max[k]))));
      check(e < 1e-3, `${name}: the casters' world box = the glTF's accessor boxes through the node transforms (max diff ${e.toExponential(1)} m)`);
      compareCascades(name, r, box);
    }
  }
}

if (process.env.ST_TEST_KEEP === '1') process.stdout.write(`work directory: ${work}\n`);
else fs.rmSync(work, { recursive: true, force: true });
process.stdout.write(failures ? `${failures} check(s) failed\n` : 'all checks passed\n');
process.exit(failures ? 1 : 0);
