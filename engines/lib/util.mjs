// Small helpers shared by the driver (engines/run.mjs): the two kinds of failure and atomic writes.
// Only node built-ins here: run.mjs imports this before it has checked the npm packages.

import fs from 'node:fs';
import path from 'node:path';

// A problem with the job or the installation, found before Chromium starts: exit 2, one line.
export class SetupError extends Error {
  constructor(message) {
    super(message);
    this.exitCode = 2;
  }
}

// A failure while running the engine (page exception, timeout, Chromium crash): exit 1.
export class RunError extends Error {
  constructor(message) {
    super(message);
    this.exitCode = 1;
  }
}

// Writes `data` to `file` so that a reader sees either the old file or the whole new one: a
// temporary file in the same directory (same file system), fsync'ed, then renamed over `file`.
export function writeFileAtomic(file, data) {
  const dir = path.dirname(file);
  const tmp = path.join(dir, `.${path.basename(file)}.${process.pid}.${Date.now()}.${Math.random().toString(36).slice(2)}.tmp`);
  const fd = fs.openSync(tmp, 'w');
  try {
    fs.writeSync(fd, data);
    fs.fsyncSync(fd);
  } catch (e) {
    fs.closeSync(fd);
    fs.rmSync(tmp, { force: true });
    throw e;
  }
  fs.closeSync(fd);
  try {
    fs.renameSync(tmp, file);
  } catch (e) {
    fs.rmSync(tmp, { force: true });
    throw e;
  }
}

export function mtimeMs(file) {
  try {
    return fs.statSync(file).mtimeMs;
  } catch {
    return -1;
  }
}
