// Waiting for the page to be free: work that must not compete with the grader's start (the
// offline copy, the search index) waits for the grader to settle, then for an idle moment.

import { ATTR, RUNTIME } from "./contract.js";

/** Resolves once the grader is ready or has failed to start (<html data-workbook-runtime>). */
export function runtimeSettled() {
  const root = document.documentElement;
  const settled = () => [RUNTIME.ready, RUNTIME.failed].includes(root.getAttribute(ATTR.runtime));
  return new Promise((resolve) => {
    if (settled()) return resolve();
    const observer = new MutationObserver(() => {
      if (!settled()) return;
      observer.disconnect();
      resolve();
    });
    observer.observe(root, { attributes: true, attributeFilter: [ATTR.runtime] });
  });
}

export const delay = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

/** The browser's next idle moment, or `timeoutMs` at the latest (at once where it cannot say). */
export const idle = (timeoutMs) =>
  new Promise((resolve) => (window.requestIdleCallback ? requestIdleCallback(() => resolve(), { timeout: timeoutMs }) : setTimeout(resolve, 0)));
