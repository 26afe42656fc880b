#!/usr/bin/env node
// shadowtune's engine driver: runs a real engine (three.js, Babylon.js) in headless Chromium on one
// job and writes the engine's own per-pixel shadow factor. Contract: engines/README.md.
//
//   node engines/run.mjs JOB.json      -> <job.out>/samples.f32, <job.out>/engine.json
//
// Exit 0 on success; 2 with one line on stderr when the job or the installation is wrong (node too
// old, Chromium missing, npm packages missing, glTF missing, unknown engine); 1 when the run fails
// (exception in the page, timeout, Chromium crash). Env: ST_CHROMIUM (default /usr/bin/chromium),
// ST_ENGINE_TIMEOUT_S (default 120), ST_ENGINE_VERBOSE=1 (forward every page console message).

// Plain ES2017 and no 'node:' specifiers up to the version check, so an old node reports itself.
import fs from 'fs';
import path from 'path';

const T0 = Date.now();
const MIN_NODE_MAJOR = 18;

function fail(e) {
  const code = e && e.exitCode ? e.exitCode : 1;
  const msg = e && e.exitCode ? e.message : (e && e.stack) || String(e);
  process.stderr.write(`engines/run.mjs: ${msg}\n`);
  process.exit(code);
}

async function main() {
  const major = Number(process.versions.node.split('.')[0]);
  if (!(major >= MIN_NODE_MAJOR)) {
    process.stderr.write(`engines/run.mjs: node ${process.versions.node} is too old (need >= ${MIN_NODE_MAJOR}): run scripts/setup.sh\n`);
    process.exit(2);
  }
  const { SetupError, RunError, writeFileAtomic } = await import('./lib/util.mjs');
  const { loadJob, ENGINES_DIR } = await import('./lib/job.mjs');

  const args = process.argv.slice(2);
  if (args.length !== 1 || args[0].startsWith('-')) {
    throw new SetupError('usage: node engines/run.mjs JOB.json');
  }
  const job = loadJob(args[0]);

  // Chromium.
  const { chromiumPath, runInChromium, preloadPuppeteer } = await import('./lib/chromium.mjs');
  const chromium = chromiumPath();
  try {
    fs.accessSync(chromium, fs.constants.X_OK);
  } catch {
    throw new SetupError(`Chromium not found or not executable at ${chromium} (set ST_CHROMIUM or run scripts/setup.sh)`);
  }

  // npm packages: every dependency of engines/package.json, at the pinned version.
  const pkg = JSON.parse(fs.readFileSync(path.join(ENGINES_DIR, 'package.json'), 'utf8'));
  const deps = { ...(pkg.dependencies || {}), ...(pkg.devDependencies || {}) };
  const missing = [];
  for (const [name, want] of Object.entries(deps)) {
    let have = null;
    try {
      have = JSON.parse(fs.readFileSync(path.join(ENGINES_DIR, 'node_modules', name, 'package.json'), 'utf8')).version;
    } catch {
      /* missing */
    }
    if (have === null) missing.push(name);
    else if (/^\d+\.\d+\.\d+/.test(want) && have !== want) missing.push(`${name} (have ${have}, want ${want})`);
  }
  if (missing.length) throw new SetupError(`npm packages missing in engines/node_modules: ${missing.join(', ')}: run scripts/setup.sh`);

  preloadPuppeteer();

  let timeoutS = 120;
  if (process.env.ST_ENGINE_TIMEOUT_S !== undefined && process.env.ST_ENGINE_TIMEOUT_S !== '') {
    timeoutS = Number(process.env.ST_ENGINE_TIMEOUT_S);
    if (!(timeoutS > 0)) throw new SetupError(`ST_ENGINE_TIMEOUT_S must be a positive number of seconds, got ${process.env.ST_ENGINE_TIMEOUT_S}`);
  }

  try {
    fs.mkdirSync(job.out, { recursive: true });
  } catch (e) {
    throw new SetupError(`cannot create the output directory ${job.out}: ${e.code || e.message}`);
  }

  const { ensureBundle } = await import('./lib/bundle.mjs');
  const bundle = await ensureBundle(job.engine);

  const { startServer } = await import('./lib/server.mjs');
  const server = await startServer({ bundle: bundle.file, gltf: job.scene.gltf, extra: job.scene.extra });
  let run;
  try {
    const pageJob = {
      engine: job.engine,
      width: job.width,
      height: job.height,
      scene: { gltf: server.urls.gltf, extra: server.urls.extra },
      camera: job.camera,
      sun: job.sun,
      settings: job.settings,
    };
    if (job.debug !== undefined) pageJob.debug = job.debug;
    run = await runInChromium({
      url: server.urls.page,
      job: pageJob,
      timeoutMs: timeoutS * 1000,
      verbose: process.env.ST_ENGINE_VERBOSE === '1',
    });
  } finally {
    await server.close();
  }

  const r = run.result;
  if (r === null || typeof r !== 'object') throw new RunError('shadowtuneRender resolved to no result object');
  if (typeof r.samples !== 'string') throw new RunError('shadowtuneRender result has no base64 "samples"');
  const samples = Buffer.from(r.samples, 'base64');
  const want = job.width * job.height * 4 * 4;
  if (samples.length !== want) {
    throw new RunError(`samples hold ${samples.length} bytes, expected ${want} (${job.width}x${job.height} RGBA float32)`);
  }

  const pageTimings = r.timings || r.pageTimings; // pageTimings: an accepted alias
  const pt = pageTimings && typeof pageTimings === 'object' ? pageTimings : {};
  const pageLoad = Number.isFinite(pt.loadMs) ? pt.loadMs : 0;
  const pageRender = Number.isFinite(pt.renderMs) ? pt.renderMs : run.timings.evalMs - pageLoad;
  const round = (x) => Math.round(x * 10) / 10;
  const meta = {
    engine: job.engine,
    version: String(r.version === undefined || r.version === null ? 'unknown' : r.version),
    width: job.width,
    height: job.height,
    format: 'f32 rgba rows top first',
    timings: {
      startMs: round(run.timings.startMs),
      loadMs: round(run.timings.gotoMs + pageLoad),
      renderMs: round(pageRender),
      totalMs: 0,
      bundleMs: round(bundle.ms),
      bundleBuilt: bundle.built,
      page: Object.fromEntries(Object.entries(pt).map(([k, v]) => [k, typeof v === 'number' ? round(v) : v])), // as the page reported them
    },
    cascades: Array.isArray(r.cascades) ? r.cascades : [],
    warnings: Array.isArray(r.warnings) ? r.warnings.map(String) : [],
  };
  // Everything else the page returned, for the logs: its "info" object plus any other keys.
  const STANDARD = new Set(['version', 'samples', 'cascades', 'warnings', 'timings', 'pageTimings', 'info']);
  const info = Object.assign({}, r.info && typeof r.info === 'object' ? r.info : {});
  for (const k of Object.keys(r)) if (!STANDARD.has(k)) info[k] = r[k];
  if (Object.keys(info).length) meta.info = info;

  writeFileAtomic(path.join(job.out, 'samples.f32'), samples);
  meta.timings.totalMs = round(Date.now() - T0);
  writeFileAtomic(path.join(job.out, 'engine.json'), JSON.stringify(meta, null, 2) + '\n');
  for (const w of meta.warnings) process.stderr.write(`engines/run.mjs: ${job.engine}: warning: ${w}\n`);
}

main().then(() => process.exit(0), fail);
