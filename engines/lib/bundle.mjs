// Bundles engines/<engine>/page.js with esbuild into engines/dist/<engine>.js, once: the bundle is
// rebuilt only when it is missing or older than package-lock.json or than any of the page's own
// (non-node_modules) source files, which esbuild's metafile lists in dist/<engine>.inputs.json.
// Writes are atomic (temp + rename), so concurrent runs never read half a bundle; two runs that
// both find it stale both build it, and the last rename wins with an identical file.

import fs from 'node:fs';
import path from 'node:path';
import { ENGINES_DIR } from './job.mjs';
import { RunError, mtimeMs, writeFileAtomic } from './util.mjs';

const DIST = path.join(ENGINES_DIR, 'dist');
const LOCK = path.join(ENGINES_DIR, 'package-lock.json');

function stale(bundle, inputsFile, entry) {
  const built = mtimeMs(bundle);
  if (built < 0) return 'missing';
  if (mtimeMs(LOCK) > built) return 'package-lock.json is newer';
  if (mtimeMs(path.join(ENGINES_DIR, 'package.json')) > built) return 'package.json is newer';
  if (mtimeMs(entry) > built) return `${path.relative(ENGINES_DIR, entry)} is newer`;
  let inputs;
  try {
    inputs = JSON.parse(fs.readFileSync(inputsFile, 'utf8'));
  } catch {
    return 'input list missing';
  }
  for (const rel of inputs) {
    const t = mtimeMs(path.join(ENGINES_DIR, rel));
    if (t < 0 || t > built) return `${rel} is newer`;
  }
  return null;
}

// Returns {file, built: bool, ms}.
export async function ensureBundle(engine) {
  const t0 = performance.now();
  const entry = path.join(ENGINES_DIR, engine, 'page.js');
  const bundle = path.join(DIST, `${engine}.js`);
  const inputsFile = path.join(DIST, `${engine}.inputs.json`);
  if (stale(bundle, inputsFile, entry) === null) return { file: bundle, built: false, ms: performance.now() - t0 };

  const esbuild = await import('esbuild');
  // ST_PACKAGE_VERSIONS in a page: {"three": "0.187.0", ...}, the installed versions of
  // engines/package.json's packages (the bundle is rebuilt whenever package-lock.json changes).
  const pkg = JSON.parse(fs.readFileSync(path.join(ENGINES_DIR, 'package.json'), 'utf8'));
  const versions = {};
  for (const name of Object.keys({ ...(pkg.dependencies || {}), ...(pkg.devDependencies || {}) })) {
    try {
      versions[name] = JSON.parse(fs.readFileSync(path.join(ENGINES_DIR, 'node_modules', name, 'package.json'), 'utf8')).version;
    } catch {
      /* run.mjs has checked them */
    }
  }
  let result;
  try {
    result = await esbuild.build({
      entryPoints: [entry],
      absWorkingDir: ENGINES_DIR,
      bundle: true,
      format: 'iife',
      platform: 'browser',
      target: ['chrome120'],
      minifyWhitespace: true,
      minifySyntax: true, // identifiers kept: page errors stay readable
      legalComments: 'none',
      define: { ST_PACKAGE_VERSIONS: JSON.stringify(versions) },
      write: false,
      metafile: true,
      logLevel: 'silent',
      outfile: bundle,
    });
  } catch (e) {
    const first = e.errors && e.errors[0];
    const where = first && first.location ? ` (${first.location.file}:${first.location.line})` : '';
    throw new RunError(`esbuild failed to bundle ${path.relative(ENGINES_DIR, entry)}: ${first ? first.text : e.message}${where}`);
  }
  fs.mkdirSync(DIST, { recursive: true });
  // the page's own files: not node_modules (package-lock.json covers those), not esbuild's
  // pseudo-inputs such as <define:...>
  const own = Object.keys(result.metafile.inputs).filter((f) => !f.startsWith('<') && !f.split(/[\\/]/).includes('node_modules'));
  writeFileAtomic(inputsFile, JSON.stringify(own, null, 1) + '\n');
  const out = result.outputFiles.find((f) => f.path === bundle) || result.outputFiles[0];
  writeFileAtomic(bundle, out.contents);
  return { file: bundle, built: true, ms: performance.now() - t0 };
}
