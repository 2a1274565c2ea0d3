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
const later = []; // the page's other messages (queries) before the theme's worker is loaded, in order
const channel = wanted ? null : new BroadcastChannel(SEARCH_CHANNEL);

function hold(event) {
  if (event.data?.type === SETUP) {
    setup = event.data;
    start();
  } else if (started) {
    later.push(event.data); // while the documents are fetched
  }
}

// The page's index has no documents (docs/hooks/search_worker.py moved them): they are fetched
// here, once search is wanted. If they cannot be (offline, and the site was never stored), the
// theme gets the index without them and finds nothing, as it would with no index.
const DOCS = new URL("../../search/search_index.docs.json", self.location.href).href;

async function documents() {
  try {
    const response = await fetch(DOCS);
    if (!response.ok) return [];
    const docs = await response.json();
    return Array.isArray(docs) ? docs : [];
  } catch {
    return [];
  }
}

async function start() {
  if (started || !wanted || !setup) return;
  started = true;
  channel?.close();
  if (!THEME_WORKER.test(name)) throw new Error(`search: not the theme's search worker: ${name}`);
  const index = setup.data;
  if (index && Array.isArray(index.docs) && index.docs.length === 0) index.docs = await documents();
  self.removeEventListener("message", hold);
  importScripts(new URL(`../javascripts/workers/${name}`, self.location.href).href);
  for (const data of [setup, ...later.splice(0)]) self.dispatchEvent(new MessageEvent("message", { data }));
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
