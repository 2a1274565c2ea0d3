// The workbook's service worker: every page and runtime file, offline.
//
// This is a template: docs/hooks/offline.py writes it to the site root (sw.js)
// after each build, with VERSION (a hash of every file) and FILES (each file's
// URL relative to the site root and its sha256, as a fetch `integrity`, or "" for
// no check) filled in.
//
// - install, first visit (no earlier version active): store nothing yet, so the
//   service worker does not compete with the page's own start for the link.
//   The page sends "store" once its runtime is ready and the browser is idle;
//   the files are then fetched through the HTTP cache, which already holds what
//   the page and its worker fetched, so nothing is downloaded twice. Each file
//   is checked against its hash (a stale copy in the HTTP cache is fetched again
//   from the network). The worker takes control of pages only once every file is
//   stored.
// - install, update (an earlier version is active): fetch every file into the
//   new version's cache, so a new version is never served half-downloaded.
// - the new version waits until the page asks it to take over (the learner
//   presses "Reload" in the update banner); activation deletes older caches.
// - fetch: files of the version are served from its cache (one version for
//   HTML, scripts and Python alike), anything else from the network. Pages and
//   workers get COOP/COEP headers, so they are cross-origin isolated and a long
//   run can be interrupted instead of the worker being killed; other cached
//   files are returned as stored (which keeps the browser's compiled-code cache
//   for them usable). A page address the site does not have gets the cached
//   404 page (offline, or when the network answers 404), with a <base> that
//   points its relative URLs at the site root.

const VERSION = __WB_VERSION__;
const FILES = __WB_FILES__;

const SCOPE = self.registration.scope;
const PREFIX = `robotics-workbook:${new URL(SCOPE).pathname}:`;
const CACHE = PREFIX + VERSION;
const KNOWN = new Set(FILES.map(([path]) => new URL(path, SCOPE).href));
const NOT_FOUND = new URL("404.html", SCOPE).href;
const ISOLATION = { "Cross-Origin-Opener-Policy": "same-origin", "Cross-Origin-Embedder-Policy": "require-corp" };

// The Python memory snapshot travels gzip-compressed (4.6 MB instead of 21 MB)
// and is stored inflated, so later starts read it as is instead of inflating it
// each time; the worker tells the two apart by gzip's magic bytes. The body is
// still checked against the file's hash as it streams through.
const INFLATE = /\.snapshot\.gz$/;
function inflated(response) {
  if (typeof DecompressionStream !== "function") return response;
  const body = response.body.pipeThrough(new DecompressionStream("gzip"));
  return new Response(body, { headers: { "Content-Type": "application/octet-stream" } });
}

/** Store every file not stored yet (a previous, interrupted run may have stored some). */
async function precache() {
  const cache = await caches.open(CACHE);
  const have = new Set((await cache.keys()).map((request) => request.url));
  const todo = FILES.filter(([path]) => !have.has(new URL(path, SCOPE).href));
  let next = 0;
  async function get(url, integrity, mode) {
    const response = await fetch(new Request(url, { cache: mode, integrity, credentials: "same-origin" }));
    if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
    return response;
  }
  async function lane() {
    while (next < todo.length) {
      const [path, integrity] = todo[next++];
      const url = new URL(path, SCOPE).href;
      // The HTTP cache first (bytes the page already fetched), the network if that copy is stale.
      const response = await get(url, integrity, "default").catch(() => get(url, integrity, "no-cache"));
      await cache.put(url, INFLATE.test(path) ? inflated(response) : response);
    }
  }
  await Promise.all(Array.from({ length: 6 }, lane));
}

/** Whether every file of this version is stored. */
async function complete() {
  const cache = await caches.open(CACHE);
  const have = new Set((await cache.keys()).map((request) => request.url));
  return FILES.every(([path]) => have.has(new URL(path, SCOPE).href));
}

let storing = null; // the store in progress, shared by every page that asks
function store() {
  storing ||= precache().finally(() => {
    storing = null;
  });
  return storing;
}

self.addEventListener("install", (event) => {
  if (self.registration.active) event.waitUntil(precache()); // an update: whole, or not at all
  else self.skipWaiting(); // the first: nothing to wait for, the page asks for the files later
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    (async () => {
      for (const name of await caches.keys()) {
        if (name.startsWith(PREFIX) && name !== CACHE) await caches.delete(name);
      }
      if (await complete()) await self.clients.claim();
    })(),
  );
});

self.addEventListener("message", (event) => {
  const reply = (message) => event.source?.postMessage({ ...message, version: VERSION });
  if (event.data?.type === "activate-update") self.skipWaiting();
  // offline.js asks which version (so which cache) serves the page, to show the stored size.
  else if (event.data?.type === "version") reply({ type: "version" });
  // offline.js asks whether the site is stored, and later asks to store it ("store").
  else if (event.data?.type === "stored?") event.waitUntil(complete().then((done) => reply({ type: "stored", complete: done })));
  else if (event.data?.type === "store") {
    event.waitUntil(
      store()
        .then(() => self.clients.claim())
        .then(() => reply({ type: "stored", complete: true }))
        .catch((err) => reply({ type: "store-failed", message: String(err?.message || err) })),
    );
  }
});

function isolate(response) {
  if (!response || response.type === "opaque" || response.type === "opaqueredirect" || response.status === 0) return response;
  const headers = new Headers(response.headers);
  for (const [name, value] of Object.entries(ISOLATION)) headers.set(name, value);
  return new Response(response.body, { status: response.status, statusText: response.statusText, headers });
}

/** The precached URL a request stands for, or null. */
function cacheKey(url) {
  url = new URL(url);
  url.search = "";
  url.hash = "";
  if (url.pathname.endsWith("/index.html")) url.pathname = url.pathname.slice(0, -"index.html".length);
  return KNOWN.has(url.href) ? url.href : null;
}

async function respond(request) {
  const key = cacheKey(request.url);
  if (key === NOT_FOUND && request.mode === "navigate") return (await notFound()) || isolate(await fetch(request));
  if (key) {
    const cached = await caches.open(CACHE).then((cache) => cache.match(key));
    // Only documents and workers need the isolation headers; everything else is
    // returned as stored, which lets the browser reuse its compiled WebAssembly.
    if (cached) return request.destination === "document" || request.destination === "worker" || request.mode === "navigate" ? isolate(cached) : cached;
  }
  if (request.mode === "navigate" && !key) {
    // "chapters/x" for "chapters/x/": send the browser to the real address.
    const url = new URL(request.url);
    url.pathname += "/";
    url.search = "";
    if (KNOWN.has(url.href)) return Response.redirect(url.href, 301);
  }
  if (request.mode !== "navigate") return isolate(await fetch(request));
  // An unknown address in the site: the network's answer, or the site's own 404
  // page when the network has none (offline) or answers "not found".
  let response;
  try {
    response = await fetch(request);
  } catch (err) {
    return (await notFound()) || Promise.reject(err);
  }
  if (response.status === 404) return (await notFound()) || isolate(response);
  return isolate(response);
}

/** The cached 404 page, its <base> set to this scope so its relative URLs work at any depth. */
async function notFound() {
  const cached = await caches.open(CACHE).then((cache) => cache.match(NOT_FOUND));
  if (!cached) return null;
  const html = (await cached.text()).replace(/<base href="[^"]*">/, `<base href="${SCOPE}">`);
  const headers = new Headers(cached.headers);
  headers.delete("Content-Length");
  return isolate(new Response(html, { status: 404, statusText: "Not Found", headers }));
}

self.addEventListener("fetch", (event) => {
  const { request } = event;
  if (request.method !== "GET" || !request.url.startsWith(SCOPE)) return;
  if (request.cache === "only-if-cached" && request.mode !== "same-origin") return;
  event.respondWith(respond(request));
});
