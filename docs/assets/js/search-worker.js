// The site's search index, built when it is wanted rather than at every page load.
//
// mkdocs-material starts its search worker as each page loads and hands it the whole site's
// index at once; the worker then builds it (about half a CPU-second on a 2-core machine), in
// competition with the grader's start. The build points the theme at this worker instead
// (docs/hooks/search_worker.py), with the theme's own worker named after the "#" of its address.
// It keeps the theme's set-up message until the page says search is wanted (search-start.js: the
// learner opens the search, or the page has been idle a while after the grader is ready), then
// loads the theme's worker and hands the message on. The theme shows "Initializing search"
// until then, as it does while its own worker builds.

import { SEARCH_ASKS, SEARCH_CHANNEL, SEARCH_WANTED } from "./search-channel.js";

const THEME_WORKER = /^search\.[0-9a-f]+\.min\.js$/; // all the "#" may name: a file of the theme's workers folder
const SETUP = 0; // the theme's message type that carries the index

const name = decodeURIComponent(self.location.hash.slice(1));
let setup = null;
let wanted = typeof BroadcastChannel === "undefined"; // no way to be told: build at once, as the theme does
let started = false;
const channel = wanted ? null : new BroadcastChannel(SEARCH_CHANNEL);

function hold(event) {
  if (event.data?.type === SETUP) {
    setup = event.data;
    start();
  }
}

function start() {
  if (started || !wanted || !setup) return;
  started = true;
  channel?.close();
  self.removeEventListener("message", hold);
  if (!THEME_WORKER.test(name)) throw new Error(`search: not the theme's search worker: ${name}`);
  importScripts(new URL(`../javascripts/workers/${name}`, self.location.href).href);
  self.dispatchEvent(new MessageEvent("message", { data: setup }));
}

self.addEventListener("message", hold);
if (channel) {
  channel.onmessage = (event) => {
    if (event.data !== SEARCH_WANTED) return;
    wanted = true;
    start();
  };
  channel.postMessage(SEARCH_ASKS);
}
