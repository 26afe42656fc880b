// A reference model of Babylon.js 9.28.0's CascadedShadowGenerator cascade set-up, written from
// engines/babylon/NOTES.md (not from Babylon's code), in float64: split distances, slice corners, the
// per-cascade light box, the caster-tightened z range, the texel snap and the light matrices. check.mjs
// compares it with what the page reports Babylon computed; the C++ side can port it line by line.
//
//   import { referenceCascades, castersBoxFromGltf } from './reference.mjs';
//   const cascades = referenceCascades(job, castersBox);   // castersBox: {min:[x,y,z], max:[x,y,z]}
//
// Matrices are column-major 16-arrays for clip = M * [x y z 1] (Babylon's Matrix.m layout). Babylon
// stores every Matrix in a Float32Array (PerformanceConfigurator.MatrixCurrentType, unless the engine
// was created with useHighPrecisionMatrix) and does the arithmetic in float64 between stores; f32()
// below marks each such store. Vector3 values stay float64.

import fs from 'node:fs';
import path from 'node:path';

const sub = (a, b) => a.map((x, i) => x - b[i]);
const add = (a, b) => a.map((x, i) => x + b[i]);
const scale = (a, s) => a.map((x) => x * s);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const len = (a) => Math.sqrt(dot(a, a));
const normalize = (a) => scale(a, 1 / len(a));
const f32 = (m) => m.map(Math.fround); // a Matrix store (Float32Array)

// NOTES.md "Conventions": Matrix.LookAtLHToRef (math.vector.pure.js:6925-6949).
export function lookAtLH(eye, target, up) {
  const z = normalize(sub(target, eye));
  let x = cross(up, z);
  const xl = dot(x, x);
  x = xl === 0 ? [1, x[1], x[2]] : scale(x, 1 / Math.sqrt(xl));
  const y = normalize(cross(z, x));
  return f32([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0, -dot(x, eye), -dot(y, eye), -dot(z, eye), 1]);
}

// Matrix.OrthoOffCenterLHToRef (math.vector.pure.js:7134-7151), halfZRange false (WebGL).
export function orthoOffCenterLH(l, r, b, t, n, f) {
  return f32([2 / (r - l), 0, 0, 0, 0, 2 / (t - b), 0, 0, 0, 0, 2 / (f - n), 0, (l + r) / (l - r), (t + b) / (b - t), -(f + n) / (f - n), 1]);
}

// column-major product a * b (apply b first), float64 arithmetic, float32 store (Matrix.multiplyToRef)
export function mul(a, b) {
  const o = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c) for (let r = 0; r < 4; ++r) for (let k = 0; k < 4; ++k) o[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return f32(o);
}

// general 4x4 inverse (cofactors), float64 arithmetic, float32 store (Matrix.invertToRef)
export function invert(m) {
  const a = (r, c) => m[c * 4 + r];
  const o = new Array(16);
  const det3 = (r0, r1, r2, c0, c1, c2) =>
    a(r0, c0) * (a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1)) - a(r0, c1) * (a(r1, c0) * a(r2, c2) - a(r1, c2) * a(r2, c0)) +
    a(r0, c2) * (a(r1, c0) * a(r2, c1) - a(r1, c1) * a(r2, c0));
  const idx = [0, 1, 2, 3];
  let det = 0;
  const cof = [];
  for (let r = 0; r < 4; ++r) {
    cof.push([]);
    for (let c = 0; c < 4; ++c) {
      const rs = idx.filter((x) => x !== r);
      const cs = idx.filter((x) => x !== c);
      cof[r].push(((r + c) % 2 ? -1 : 1) * det3(rs[0], rs[1], rs[2], cs[0], cs[1], cs[2]));
    }
  }
  for (let c = 0; c < 4; ++c) det += a(0, c) * cof[0][c];
  for (let r = 0; r < 4; ++r) for (let c = 0; c < 4; ++c) o[r * 4 + c] = cof[r][c] / det; // inverse(r',c') = cof(c',r')/det, column-major
  return f32(o);
}

// Vector3.TransformCoordinates (math.vector.pure.js:2184-2195): with the w divide.
export function transformPoint(m, p) {
  const x = p[0] * m[0] + p[1] * m[4] + p[2] * m[8] + m[12];
  const y = p[0] * m[1] + p[1] * m[5] + p[2] * m[9] + m[13];
  const z = p[0] * m[2] + p[1] * m[6] + p[2] * m[10] + m[14];
  const w = p[0] * m[3] + p[1] * m[7] + p[2] * m[11] + m[15];
  return [x / w, y / w, z / w];
}

// The camera as shadowtune builds it (renderer/csm/frustum.cpp): glm::lookAtRH basis, vertical fov.
function cameraBasis(cam) {
  const f = normalize(sub(cam.target, cam.position));
  const up = Math.abs(f[1]) > 0.9998477 ? [0, 0, 1] : [0, 1, 0];
  const s = normalize(cross(f, up));
  return { s, u: cross(s, f), f };
}

// The camera's view and projection as float32 matrices (glm::lookAtRH / glm::perspective values).
export function cameraMatrices(cam, aspect) {
  const { s, u, f } = cameraBasis(cam);
  const p = cam.position;
  const view = f32([s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, p), -dot(u, p), dot(f, p), 1]);
  const t = 1 / Math.tan((cam.fovY * Math.PI) / 360);
  const n = cam.near;
  const fa = cam.far;
  const proj = f32([t / aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, -(fa + n) / (fa - n), -1, 0, 0, (-2 * fa * n) / (fa - n), 0]);
  return { view, proj };
}

// World corners of the slice between the break fractions b0 and b1 of [near, far] (NOTES.md "Slice
// corners"): the 8 NDC corners unprojected through the float32 inverse of the camera's
// view-projection (z -1 near, +1 far), then each near->far edge cut at b0 and b1.
export function sliceCorners(cam, aspect, b0, b1, matrices = cameraMatrices(cam, aspect)) {
  const inv = invert(mul(matrices.proj, matrices.view));
  const ndc = [[-1, 1, -1], [1, 1, -1], [1, -1, -1], [-1, -1, -1], [-1, 1, 1], [1, 1, 1], [1, -1, 1], [-1, -1, 1]];
  const w = ndc.map((c) => transformPoint(inv, c));
  const out = new Array(8);
  for (let k = 0; k < 4; ++k) {
    const edge = sub(w[k + 4], w[k]);
    out[k] = add(w[k], scale(edge, b0));
    out[k + 4] = add(w[k], scale(edge, b1));
  }
  return out;
}

// NOTES.md "Split distances" (cascadedShadowGenerator.pure.js:331-349).
export function splits({ near, far, lambda = 0.5, numCascades = 4, shadowMaxZ = far, minDistance = 0, maxDistance = 1 }) {
  const cameraRange = far - near;
  const maxD = shadowMaxZ < far && shadowMaxZ >= near ? Math.min((shadowMaxZ - near) / (far - near), maxDistance) : maxDistance;
  const minZ = near + minDistance * cameraRange;
  const maxZ = near + maxD * cameraRange;
  const range = maxZ - minZ;
  const ratio = maxZ / minZ;
  const out = [];
  let prev = minDistance;
  for (let i = 0; i < numCascades; ++i) {
    const p = (i + 1) / numCascades;
    const log = minZ * ratio ** p;
    const uniform = minZ + range * p;
    const d = lambda * (log - uniform) + uniform;
    const brk = (d - near) / cameraRange;
    out.push({ prevBreakDistance: prev, breakDistance: brk, splitFar: d, frustumLength: (brk - prev) * cameraRange });
    prev = brk;
  }
  return out;
}

// NOTES.md "The light box", "The z range", "Projection and texel snap".
// cameraMatrices: optional {view, proj} (float32 column-major) to use instead of the glm-style camera,
// e.g. the page's info.camera (Babylon's own camera matrices).
export function referenceCascades(job, castersBox, camMatrices) {
  const s = job.settings ?? {};
  const cam = job.camera;
  const aspect = job.width / job.height;
  const numCascades = Math.min(Math.max(s.numCascades ?? 4, 2), 4);
  const mapSize = s.mapSize ?? 1024;
  const depthClamp = s.depthClamp ?? true;
  const pcss = String(s.filter ?? 'PCF').toUpperCase() === 'PCSS';
  let dir = normalize(job.sun.direction);
  if (Math.abs(dot(dir, [0, 1, 0])) === 1) dir = [dir[0], dir[1], 1e-13];
  const up = [0, 1, 0];
  const brk = splits({ near: cam.near, far: cam.far, lambda: s.lambda ?? 0.5, numCascades, shadowMaxZ: s.shadowMaxZ ?? cam.far });
  const boxCorners = [];
  for (const x of [castersBox.min[0], castersBox.max[0]])
    for (const y of [castersBox.min[1], castersBox.max[1]])
      for (const z of [castersBox.min[2], castersBox.max[2]]) boxCorners.push([x, y, z]);

  return brk.map((b, i) => {
    const range = cam.far - cam.near;
    const corners = sliceCorners(cam, aspect, b.prevBreakDistance, b.breakDistance, camMatrices);
    const center = scale(corners.reduce(add, [0, 0, 0]), 1 / 8);
    let minE;
    let maxE;
    if (s.stabilizeCascades) {
      let r = 0;
      for (const c of corners) r = Math.max(r, len(sub(c, center)));
      r = Math.ceil(r * 16) / 16;
      minE = [-r, -r, -r];
      maxE = [r, r, r];
    } else {
      const tmp = lookAtLH(center, add(center, dir), up);
      minE = [Infinity, Infinity, Infinity];
      maxE = [-Infinity, -Infinity, -Infinity];
      for (const c of corners) {
        const v = transformPoint(tmp, c);
        for (let k = 0; k < 3; ++k) { minE[k] = Math.min(minE[k], v[k]); maxE[k] = Math.max(maxE[k], v[k]); }
      }
    }
    const shadowCameraPos = add(center, scale(dir, minE[2]));
    const view = lookAtLH(shadowCameraPos, center, up);
    let n = 0;
    let f = maxE[2] - minE[2];
    let cMin = Infinity;
    let cMax = -Infinity;
    for (const c of boxCorners) { const z = transformPoint(view, c)[2]; cMin = Math.min(cMin, z); cMax = Math.max(cMax, z); }
    if (!(cMin > f)) {
      if (!depthClamp || pcss) {
        n = Math.min(n, cMin);
        if (!pcss) f = Math.min(f, cMax);
      } else {
        f = Math.min(f, cMax);
        n = Math.max(n, cMin);
        f = Math.max(n + 1, f);
      }
    }
    let proj = orthoOffCenterLH(minE[0], maxE[0], minE[1], maxE[1], n, f);
    const o = transformPoint(mul(proj, view), [0, 0, 0]).map((x) => (x * mapSize) / 2);
    const off = [(Math.round(o[0]) - o[0]) * (2 / mapSize), (Math.round(o[1]) - o[1]) * (2 / mapSize)];
    const T = f32([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, off[0], off[1], 0, 1]);
    proj = mul(T, proj);
    return {
      index: i, splitNear: cam.near + b.prevBreakDistance * range, splitFar: b.splitFar, prevBreakDistance: b.prevBreakDistance,
      breakDistance: b.breakDistance, frustumLength: b.frustumLength, minExtents: [minE[0], minE[1], n], maxExtents: [maxE[0], maxE[1], f],
      frustumCenter: center, shadowCameraPos, viewMatrix: view, projectionMatrix: proj, transformMatrix: mul(proj, view), snapOffsetNdc: off,
    };
  });
}

// ---------------------------------------------------------------------------------------------
// The casters' box Babylon uses (NOTES.md "The z range"): the union over every mesh of the AABB of its
// local box's 8 corners in world space, the local box being the glTF POSITION accessor's min/max.

function trsMatrix(node) {
  if (node.matrix) return node.matrix.slice();
  const [tx, ty, tz] = node.translation ?? [0, 0, 0];
  const [qx, qy, qz, qw] = node.rotation ?? [0, 0, 0, 1];
  const [sx, sy, sz] = node.scale ?? [1, 1, 1];
  const r = [
    1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + qz * qw), 2 * (qx * qz - qy * qw),
    2 * (qx * qy - qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz + qx * qw),
    2 * (qx * qz + qy * qw), 2 * (qy * qz - qx * qw), 1 - 2 * (qx * qx + qy * qy),
  ];
  return [r[0] * sx, r[1] * sx, r[2] * sx, 0, r[3] * sy, r[4] * sy, r[5] * sy, 0, r[6] * sz, r[7] * sz, r[8] * sz, 0, tx, ty, tz, 1];
}

function readGltfJson(file) {
  const buf = fs.readFileSync(file);
  if (buf.readUInt32LE(0) === 0x46546c67) return JSON.parse(buf.subarray(20, 20 + buf.readUInt32LE(12)).toString('utf8'));
  return JSON.parse(buf.toString('utf8'));
}

export function castersBoxFromGltf(files) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (const file of files.filter(Boolean)) {
    const g = readGltfJson(path.resolve(file));
    const visit = (idx, parent) => {
      const node = g.nodes[idx];
      const world = mul(parent, trsMatrix(node));
      if (node.mesh !== undefined) {
        for (const prim of g.meshes[node.mesh].primitives) {
          const acc = g.accessors[prim.attributes.POSITION];
          for (const x of [acc.min[0], acc.max[0]])
            for (const y of [acc.min[1], acc.max[1]])
              for (const z of [acc.min[2], acc.max[2]]) {
                const p = transformPoint(world, [x, y, z]);
                for (let k = 0; k < 3; ++k) { min[k] = Math.min(min[k], p[k]); max[k] = Math.max(max[k], p[k]); }
              }
        }
      }
      for (const c of node.children ?? []) visit(c, world);
    };
    const I = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
    for (const root of g.scenes[g.scene ?? 0].nodes) visit(root, I);
  }
  return { min, max };
}
