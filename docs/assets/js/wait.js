// Waiting for the page to be free: work that must not compete with the grader's start (the
// offline copy, the search index, a Build exercise's editor and sandbox) waits for the grader
// to settle, then for an idle moment.

import { ATTR, RUNTIME } from "./contract.js";

/** Resolves once the grader is in one of `states` (<html data-workbook-runtime>). */
function runtimeIn(states) {
  const root = document.documentElement;
  const there = () => states.includes(root.getAttribute(ATTR.runtime));
  return new Promise(/** @param {(value?: void) => void} resolve */ (resolve) => {
    if (there()) return resolve();
    const observer = new MutationObserver(() => {
      if (!there()) return;
      observer.disconnect();
      resolve();
    });
    observer.observe(root, { attributes: true, attributeFilter: [ATTR.runtime] });
  });
}

/** Resolves once the grader is ready or has failed to start. */
export const runtimeSettled = () => runtimeIn([RUNTIME.ready, RUNTIME.failed]);

/** Resolves once the grader is ready (not merely given up on). */
export const runtimeReady = () => runtimeIn([RUNTIME.ready]);

/** @returns {Promise<void>} */
export const delay = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

/** The browser's next idle moment, or `timeoutMs` at the latest (at once where it cannot say). */
/** @returns {Promise<void>} */
export const idle = (timeoutMs) =>
  new Promise((resolve) => (window.requestIdleCallback
    ? requestIdleCallback(() => resolve(), { timeout: timeoutMs })
    : setTimeout(resolve, 0)));
