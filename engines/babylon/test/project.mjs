// Where shadowtune's GL camera puts world points (renderer/csm/frustum.cpp: glm::lookAtRH basis with
// stableUp, glm::perspective), compared with Babylon's own camera matrices from engine.json:
//   node project.mjs JOB.json OUT/engine.json x,y,z [x,y,z ...]
// Prints pixel coordinates (x right, y down, pixel centres at +0.5) from both and the matrices' largest
// difference.
import fs from 'node:fs';

const [jobFile, engineFile, ...pts] = process.argv.slice(2);
const job = JSON.parse(fs.readFileSync(jobFile, 'utf8'));
const eng = JSON.parse(fs.readFileSync(engineFile, 'utf8'));
const { position: p, target: t, fovY, near, far } = job.camera;
const sub = (a, b) => a.map((x, i) => x - b[i]);
const dot = (a, b) => a.reduce((s, x, i) => s + x * b[i], 0);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => a.map((x) => x / Math.hypot(...a));
const f = norm(sub(t, p));
const up = Math.abs(f[1]) > 0.9998477 ? [0, 0, 1] : [0, 1, 0];
const s = norm(cross(f, up));
const u = cross(s, f);
// column-major like glm / Babylon's .m
const view = [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, p), -dot(u, p), dot(f, p), 1];
const aspect = job.width / job.height;
const th = Math.tan((fovY * Math.PI) / 360);
const proj = [1 / (aspect * th), 0, 0, 0, 0, 1 / th, 0, 0, 0, 0, -(far + near) / (far - near), -1, 0, 0, -(2 * far * near) / (far - near), 0];
const mul = (m, v) => [0, 1, 2, 3].map((r) => m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3]);
const maxDiff = (a, b) => Math.max(...a.map((x, i) => Math.abs(x - b[i])));
console.log(`view max |glm - babylon| = ${maxDiff(view, eng.camera.viewMatrix).toExponential(2)}, projection ${maxDiff(proj, eng.camera.projectionMatrix).toExponential(2)}`);
for (const pt of pts) {
  const w = pt.split(',').map(Number);
  for (const [name, V, P] of [['glm', view, proj], ['babylon', eng.camera.viewMatrix, eng.camera.projectionMatrix]]) {
    const c = mul(P, mul(V, [...w, 1]));
    const ndc = c.map((x) => x / c[3]);
    const px = ((ndc[0] + 1) / 2) * job.width;
    const py = ((1 - ndc[1]) / 2) * job.height;
    console.log(`${pt} ${name}: pixel (${px.toFixed(2)}, ${py.toFixed(2)}) ndc z ${ndc[2].toFixed(5)}`);
  }
}
