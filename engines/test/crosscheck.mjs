// Checks the three.js hook against three.js's own shading: for each settings variant, renders the
// job three times with the driver (engines/run.mjs):
//   factor      the capture (what shadowtune reads)
//   colour      three.js's own linear colour, shadows on          (job.debug.output = "colour")
//   unshadowed  the same with receiveShadow off on every mesh      (+ job.debug.receiveShadow = false)
// The scene has no ambient or environment light, so wherever N.L > 0 the colour is all direct sun
// light and colour / unshadowed must equal the captured factor (fade bands included).
//   node engines/test/crosscheck.mjs JOB.json ['{"fade":true}' ...]   (default variants: {} and {"fade":true})
// Exit 0 when every variant matches to 1e-4, 1 otherwise.

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

const RUN = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..', 'run.mjs');
const jobFile = path.resolve(process.argv[2] || '');
const base = JSON.parse(fs.readFileSync(jobFile, 'utf8'));
const variants = process.argv.length > 3 ? process.argv.slice(3).map((a) => JSON.parse(a)) : [{}, { fade: true }];
const root = path.resolve(path.dirname(jobFile), base.out || jobFile.replace(/\.json$/, '.out')) + '.crosscheck';

function render(name, settings, debug) {
  const job = { ...base, settings: { ...base.settings, ...settings }, out: path.join(root, name) };
  if (debug) job.debug = debug;
  const file = path.join(root, `${name}.json`);
  fs.mkdirSync(root, { recursive: true });
  fs.writeFileSync(file, JSON.stringify(job, null, 1));
  const r = spawnSync(process.execPath, [RUN, file], { stdio: ['ignore', 'inherit', 'inherit'] });
  if (r.status !== 0) {
    process.stdout.write(`FAIL run.mjs exited ${r.status} on ${file}\n`);
    process.exit(1);
  }
  const b = fs.readFileSync(path.join(job.out, 'samples.f32'));
  return new Float32Array(b.buffer.slice(b.byteOffset, b.byteOffset + b.length));
}

let failed = 0;
for (const [k, v] of variants.entries()) {
  const F = render(`v${k}-factor`, v);
  const C = render(`v${k}-colour`, v, { output: 'colour' });
  const U = render(`v${k}-unshadowed`, v, { output: 'colour', receiveShadow: false });
  let n = 0;
  let partial = 0;
  let maxd = 0;
  let worst = null;
  for (let i = 0; i < F.length; i += 4) {
    if (F[i + 3] !== 1 || !(F[i + 2] > 0.05)) continue;
    let c = 0;
    for (let j = 1; j < 3; j++) if (U[i + j] > U[i + c]) c = j;
    if (!(U[i + c] > 1e-3)) continue;
    const ratio = C[i + c] / U[i + c];
    const d = Math.abs(ratio - F[i]);
    n++;
    if (F[i] > 0.02 && F[i] < 0.98) partial++;
    if (d > maxd) {
      maxd = d;
      worst = { pixel: [(i / 4) % base.width, Math.floor(i / 4 / base.width)], factor: F[i], ratio };
    }
  }
  const ok = n > 100 && maxd < 1e-4;
  if (!ok) failed++;
  process.stdout.write(`${ok ? 'ok  ' : 'FAIL'} settings ${JSON.stringify(v)}: ${n} sunlit pixels (${partial} partly shadowed), max |colour/unshadowed - factor| = ${maxd.toExponential(2)}${worst && !ok ? ` at ${JSON.stringify(worst)}` : ''}\n`);
}
if (failed) process.exit(1);
process.stdout.write('the captured factor is what three.js applies\n');
