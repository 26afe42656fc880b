// Runs one job in Debian's headless Chromium (SwiftShader WebGL) through puppeteer-core: launch with a
// fresh temporary profile, open the served page, call window.shadowtuneRender(job), return its result.
// Page console errors/warnings go to stderr; an uncaught page exception fails the run.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { RunError } from './util.mjs';

export const CHROMIUM_ARGS = [
  '--headless=new',
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-gpu-sandbox',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-quic',
  '--mute-audio',
];

// puppeteer-core takes 0.2-0.9 s to import on a loaded machine: run.mjs starts it early, in parallel
// with bundling and serving.
let puppeteerImport = null;
export function preloadPuppeteer() {
  if (!puppeteerImport) {
    puppeteerImport = import('puppeteer-core');
    puppeteerImport.catch(() => {});
  }
  return puppeteerImport;
}

export function chromiumPath() {
  return process.env.ST_CHROMIUM || '/usr/bin/chromium';
}

function say(line) {
  process.stderr.write(line.endsWith('\n') ? line : line + '\n');
}

// opts: {url, job (as the page sees it), timeoutMs, verbose}. Resolves to
// {result, timings: {startMs, gotoMs, evalMs}}. Always closes Chromium and removes the profile.
export async function runInChromium(opts) {
  const puppeteer = (await preloadPuppeteer()).default;
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'shadowtune-chromium-'));
  let browser = null;
  let timer = null;
  let pageFailure = null; // first uncaught page exception
  let rejectFailure;
  const failure = new Promise((_, reject) => {
    rejectFailure = reject;
  });
  failure.catch(() => {});

  let launching = null; // puppeteer.launch() in flight: a signal may arrive before it resolves
  const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
  const cleanup = async () => {
    clearTimeout(timer);
    if (!browser && launching) browser = await Promise.race([launching.catch(() => null), sleep(5000).then(() => null)]);
    if (browser) {
      const b = browser;
      browser = null;
      const proc = b.process();
      await Promise.race([b.close().catch(() => {}), sleep(3000)]);
      if (proc && proc.exitCode === null && proc.signalCode === null) {
        const exited = new Promise((r) => proc.once('exit', r));
        proc.kill('SIGKILL');
        await Promise.race([exited, sleep(2000)]);
      }
    }
    fs.rmSync(profile, { recursive: true, force: true, maxRetries: 5, retryDelay: 100 });
  };
  const onSignal = (sig) => {
    cleanup().finally(() => process.exit(sig === 'SIGINT' ? 130 : 143));
  };
  process.once('SIGINT', onSignal);
  process.once('SIGTERM', onSignal);

  timer = setTimeout(() => {
    rejectFailure(new RunError(`timed out after ${opts.timeoutMs / 1000} s (ST_ENGINE_TIMEOUT_S)`));
  }, opts.timeoutMs);

  const race = (p) => Promise.race([p, failure]);
  try {
    const t0 = performance.now();
    try {
      launching = puppeteer.launch({
        executablePath: chromiumPath(),
        headless: true,
        args: CHROMIUM_ARGS,
        userDataDir: profile,
        pipe: true,
        timeout: opts.timeoutMs,
        protocolTimeout: opts.timeoutMs,
        defaultViewport: { width: 64, height: 64 },
        handleSIGINT: false,
        handleSIGTERM: false,
        handleSIGHUP: false,
      });
      browser = await race(launching);
    } catch (e) {
      if (e instanceof RunError) throw e;
      throw new RunError(`cannot start Chromium (${chromiumPath()}): ${String(e.message).split('\n')[0]}`);
    }
    browser.on('disconnected', () => {
      rejectFailure(new RunError('Chromium exited or disconnected during the run'));
    });
    const page = (await browser.pages())[0] || (await browser.newPage());
    const startMs = performance.now() - t0;

    page.on('console', (msg) => {
      const type = msg.type();
      const text = msg.text();
      // ANGLE's performance notes ("GPU stall due to ReadPixels") are not problems of the run.
      if (!opts.verbose && /GL Driver Message \(OpenGL, Performance/.test(text)) return;
      if (type === 'error' || type === 'warn' || opts.verbose) say(`page ${type}: ${text}`);
    });
    page.on('pageerror', (err) => {
      const text = err && err.message ? err.message : String(err);
      say(`page exception: ${err && err.stack ? err.stack : text}`);
      if (!pageFailure) {
        pageFailure = text;
        rejectFailure(new RunError(`exception in the page: ${text.split('\n')[0]}`));
      }
    });
    if (opts.verbose) {
      page.on('request', (req) => say(`page request: ${req.method()} ${req.url()}`));
      page.on('requestfinished', (req) => say(`page request done: ${req.url()}`));
    }
    page.on('requestfailed', (req) => {
      const why = req.failure()?.errorText;
      // Chromium reports ERR_ABORTED for a complete response whose body the page read through
      // response.body.getReader() (three.js's FileLoader does, for progress events): not a failure.
      const res = req.response();
      if (why === 'net::ERR_ABORTED' && res && res.ok() && !opts.verbose) return;
      say(`page request failed: ${req.url()} (${why}${res ? `, status ${res.status()}` : ''})`);
    });
    page.on('response', (res) => {
      if (res.status() >= 400) say(`page request ${res.status()}: ${res.url()}`);
    });

    const t1 = performance.now();
    await race(page.goto(opts.url, { waitUntil: 'load', timeout: opts.timeoutMs }));
    const hasEntry = await race(page.evaluate(() => typeof window.shadowtuneRender === 'function'));
    if (!hasEntry) throw new RunError('the page did not define window.shadowtuneRender');
    const gotoMs = performance.now() - t1;

    const t2 = performance.now();
    let result;
    try {
      result = await race(page.evaluate((job) => window.shadowtuneRender(job), opts.job));
    } catch (e) {
      if (e instanceof RunError) throw e;
      throw new RunError(`shadowtuneRender failed: ${String(e.message).split('\n')[0]}`);
    }
    const evalMs = performance.now() - t2;
    if (pageFailure) throw new RunError(`exception in the page: ${pageFailure.split('\n')[0]}`);
    return { result, timings: { startMs, gotoMs, evalMs } };
  } finally {
    process.off('SIGINT', onSignal);
    process.off('SIGTERM', onSignal);
    await cleanup();
  }
}
