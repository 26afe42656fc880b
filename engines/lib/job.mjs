// Reads and validates a job (engines/README.md, "The job"). Every problem is a SetupError: one line,
// exit 2. Relative paths in the job resolve against the job file's directory.

import fs from 'node:fs';
import path from 'node:path';
import { SetupError } from './util.mjs';

export const ENGINES_DIR = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..');

// Engines are the directories of engines/ that hold a page.js.
export function knownEngines() {
  return fs.readdirSync(ENGINES_DIR, { withFileTypes: true })
    .filter((d) => d.isDirectory() && fs.existsSync(path.join(ENGINES_DIR, d.name, 'page.js')))
    .map((d) => d.name)
    .sort();
}

function isNum(x) {
  return typeof x === 'number' && Number.isFinite(x);
}

function vec3(x, what) {
  if (!Array.isArray(x) || x.length !== 3 || !x.every(isNum)) {
    throw new SetupError(`job: ${what} must be an array of 3 finite numbers, got ${JSON.stringify(x)}`);
  }
  return x.slice();
}

function sceneFile(value, what, base, exts) {
  if (value === null || value === undefined || value === '') return null;
  if (typeof value !== 'string') throw new SetupError(`job: ${what} must be a path or null`);
  const file = path.resolve(base, value);
  let st;
  try {
    st = fs.statSync(file);
  } catch {
    throw new SetupError(`job: ${what} not found: ${file}`);
  }
  if (!st.isFile()) throw new SetupError(`job: ${what} is not a file: ${file}`);
  const ext = path.extname(file).toLowerCase();
  if (!exts.includes(ext)) throw new SetupError(`job: ${what} must end in ${exts.join(' or ')}: ${file}`);
  return file;
}

export function loadJob(jobPath) {
  const jobFile = path.resolve(jobPath);
  let text;
  try {
    text = fs.readFileSync(jobFile, 'utf8');
  } catch (e) {
    throw new SetupError(`job: cannot read ${jobFile}: ${e.code || e.message}`);
  }
  let job;
  try {
    job = JSON.parse(text);
  } catch (e) {
    throw new SetupError(`job: ${jobFile} is not valid JSON: ${e.message}`);
  }
  if (job === null || typeof job !== 'object' || Array.isArray(job)) throw new SetupError(`job: ${jobFile} must hold a JSON object`);
  const base = path.dirname(jobFile);

  const engines = knownEngines();
  if (typeof job.engine !== 'string' || !engines.includes(job.engine)) {
    throw new SetupError(`job: unknown engine ${JSON.stringify(job.engine)} (known: ${engines.join(', ') || 'none'})`);
  }

  for (const k of ['width', 'height']) {
    if (!Number.isInteger(job[k]) || job[k] < 1 || job[k] > 8192) {
      throw new SetupError(`job: ${k} must be an integer in 1..8192, got ${JSON.stringify(job[k])}`);
    }
  }

  const scene = job.scene;
  if (scene === null || typeof scene !== 'object') throw new SetupError('job: scene must be an object {gltf, extra}');
  const gltf = sceneFile(scene.gltf, 'scene.gltf', base, ['.gltf', '.glb']);
  const extra = sceneFile(scene.extra, 'scene.extra', base, ['.glb', '.gltf']);
  if (gltf === null && extra === null) throw new SetupError('job: scene.gltf and scene.extra are both null: nothing to render');

  const cam = job.camera;
  if (cam === null || typeof cam !== 'object') throw new SetupError('job: camera must be an object');
  const camera = {
    position: vec3(cam.position, 'camera.position'),
    target: vec3(cam.target, 'camera.target'),
    fovY: cam.fovY, near: cam.near, far: cam.far,
  };
  if (!isNum(camera.fovY) || camera.fovY <= 0 || camera.fovY >= 180) throw new SetupError(`job: camera.fovY must be in (0, 180) degrees, got ${JSON.stringify(cam.fovY)}`);
  if (!isNum(camera.near) || camera.near <= 0) throw new SetupError(`job: camera.near must be > 0, got ${JSON.stringify(cam.near)}`);
  if (!isNum(camera.far) || camera.far <= camera.near) throw new SetupError(`job: camera.far must be > camera.near, got ${JSON.stringify(cam.far)}`);
  const d = camera.target.map((t, i) => t - camera.position[i]);
  if (Math.hypot(...d) === 0) throw new SetupError('job: camera.target equals camera.position');

  if (job.sun === null || typeof job.sun !== 'object') throw new SetupError('job: sun must be an object {direction}');
  const dir = vec3(job.sun.direction, 'sun.direction');
  const len = Math.hypot(...dir);
  if (!(len > 0)) throw new SetupError('job: sun.direction must not be zero');

  const settings = job.settings === undefined || job.settings === null ? {} : job.settings;
  if (typeof settings !== 'object' || Array.isArray(settings)) throw new SetupError('job: settings must be an object');

  let out = job.out;
  if (out === undefined || out === null || out === '') {
    out = jobFile.replace(/\.json$/i, '') + '.out';
  } else if (typeof out !== 'string') {
    throw new SetupError('job: out must be a directory path');
  }
  out = path.resolve(base, out);

  if (job.debug !== undefined && (job.debug === null || typeof job.debug !== 'object' || Array.isArray(job.debug))) {
    throw new SetupError('job: debug must be an object when given');
  }

  return {
    file: jobFile,
    engine: job.engine,
    width: job.width,
    height: job.height,
    scene: { gltf, extra },
    camera,
    sun: { direction: dir.map((x) => x / len) },
    settings,
    out,
    debug: job.debug, // tests only: passed to the page as is
  };
}
