// The start's progress: bytes of Pyodide's runtime files counted as they arrive, and the step the
// start is at (boot-steps.js), told to the caller's onProgress (boot.js's startPyodide). The files'
// sizes come from the build (scripts/bundle.mjs defines BOOT_SIZES: real bytes, known at build time).
/* global BOOT_SIZES */
import { BOOT_STEP, STEP_ORDER } from "./boot-steps.js";

const SIZES = typeof BOOT_SIZES === "object" ? BOOT_SIZES : {}; // file name -> bytes

/** `url`'s file name in the Pyodide folder `indexURL`, or null. */
export const fileIn = (indexURL, url) =>
  (String(url).startsWith(indexURL) ? String(url).slice(indexURL.length) : null);

/** The meter of one start over `files` (names in `indexURL`), reporting to `onProgress`. */
export function progressMeter(indexURL, files, onProgress) {
  const loaded = new Map(); // file name -> bytes so far
  const expected = new Map(files.map((name) => [name, SIZES[name] || 0]));
  let phase = "download";
  /** @type {string} */
  let step = BOOT_STEP.download;
  let last = 0;
  const report = (force) => {
    if (!onProgress) return;
    const now = performance.now();
    if (!force && now - last < 100) return;
    last = now;
    let done = 0;
    for (const [name, size] of expected) done += Math.min(loaded.get(name) || 0, size || Infinity);
    const total = [...expected.values()].reduce((a, b) => a + b, 0);
    // Every file is in, or Python has started and imports (a file left uncounted must not hold the phase back).
    if (phase === "download" && (done >= total || step === BOOT_STEP.import)) phase = "start";
    const shown = phase === "start" && step === BOOT_STEP.download ? BOOT_STEP.compile : step;
    onProgress({ phase, loaded: Math.min(done, total), total, step: shown });
  };
  return {
    /** Count `response`'s body as it arrives (a clone: the original goes on untouched). */
    watch(name, response) {
      if (!expected.has(name) || !response?.body) return response;
      const reader = response.clone().body.getReader();
      (async () => {
        let n = 0;
        for (;;) {
          const { done, value } = await reader.read();
          if (done) break;
          n += value.byteLength;
          loaded.set(name, n);
          report(false);
        }
        loaded.set(name, Math.max(n, expected.get(name)));
        report(true);
      })().catch(() => {});
      return response;
    },
    done(name) {
      loaded.set(name, expected.get(name) || 0);
      report(true);
    },
    drop(name) {
      expected.delete(name);
      report(true);
    },
    /** Count the files `to` instead of `from` (the start took others for the same part). */
    swap(from, ...to) {
      expected.delete(from);
      for (const name of to) expected.set(name, SIZES[name] || 0);
      report(true);
    },
    phase(next) {
      phase = next;
      report(true);
    },
    /** What the worker does now (never an earlier step than the one told before). */
    step(next) {
      if (STEP_ORDER.indexOf(next) <= STEP_ORDER.indexOf(step)) return;
      step = next;
      report(true);
    },
    fileName: (url) => fileIn(indexURL, url),
  };
}
