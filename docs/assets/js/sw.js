// The workbook's service worker: every page and runtime file, offline, and only as built.
//
// This is a template: docs/hooks/offline.py writes it to the site root (sw.js)
// after each build, with VERSION (a hash of every file) and FILES, the manifest:
// per file [URL relative to the site root, "sha256-…" of its bytes, size] and,
// for the memory snapshot (stored inflated), the sha256 and size as stored.
//
// The manifest in this script is the one thing on the origin that page script
// cannot rewrite; Cache Storage can be written by anything on the origin. So:
// - serving: a stored response is served only if its bytes still hash to the
//   manifest's value. A mismatch is deleted, and the file fetched from the
//   network (checked by the same hash); offline it is refused, never served.
//   (The grader's worker reads its two largest files from Cache Storage itself,
//   checked against the same hashes: stored-copy.js.)
// - the copy: started by the page once the learner agreed (offline.js); the
//   wish is kept in the "state" cache, so any later event (a navigation, a
//   reload, a message) resumes it from what is already stored and verified.
//   Each file is fetched through the HTTP cache (bytes the page already has),
//   or the network if that copy is stale, and verified as stored.
// - "stored": only when every manifest entry is in the cache and verified; the
//   SW then writes a seal (the manifest's version and count) into the cache.
//   Pages ask the SW ("status") and never infer it from being controlled.
// - install, first visit: nothing is stored (the page asks later); an update
//   (an earlier version active, the copy wanted): the new version is copied
//   whole before it can take over, unchanged files from the old cache.
// - LATER (the sandbox's snapshot): not part of the copy; kept, in the same
//   cache, when it is first fetched for a learner who wants the copy.
// - sitemap.xml (which mkdocs-material's instant navigation reads) is written
//   here from the manifest's pages, for this scope: right at any address.
// - pages and workers get COOP/COEP headers (cross-origin isolation: a long run
//   can be interrupted); other stored files are returned with their stored
//   headers, their bytes served from the stored Blob that was hashed (see
//   genuine()). An unknown address gets the stored 404 page, its <base> pointed
//   at this scope.

const VERSION = __WB_VERSION__;
const FILES = __WB_FILES__;
const WIRE_BYTES = __WB_WIRE_BYTES__; // the whole copy's download, gzip as the host sends it (offline.py)
const LATER = __WB_LATER__; // kept when first fetched, not with the copy (offline.py): the sandbox's snapshot

// The global scope, as what it is: a service worker's (the type checker's lib names it a worker's).
const sw = /** @type {ServiceWorkerGlobalScope} */ (/** @type {unknown} */ (self));
const SCOPE = sw.registration.scope;
const PREFIX = `robotics-workbook:${new URL(SCOPE).pathname}:`;
const CACHE = PREFIX + VERSION;
const STATE = PREFIX + "state"; // not versioned: whether the learner wants the copy
const WANTED = new URL("__wb__/wanted", SCOPE).href;
const SEAL = new URL("__wb__/verified", SCOPE).href;
/** @returns {[string, {path: string, integrity: string, size: number, hashes: string[], storedSize: number}]} */
const entryOf = ([path, integrity, size, storedIntegrity, storedSize]) => [new URL(path, SCOPE).href,
  { path, integrity, size, hashes: [integrity, storedIntegrity].filter(Boolean), storedSize: storedSize || size }];
const ENTRIES = new Map(FILES.map(entryOf));
const LATER_ENTRIES = new Map(LATER.map(entryOf));
const TOTAL_BYTES = [...ENTRIES.values()].reduce((n, e) => n + e.storedSize, 0);
const NOT_FOUND = new URL("404.html", SCOPE).href;
const SITEMAP = new URL("sitemap.xml", SCOPE).href;
const ISOLATION = { "Cross-Origin-Opener-Policy": "same-origin", "Cross-Origin-Embedder-Policy": "require-corp" };
const LANES = 4;

// ---- Hashes ------------------------------------------------------------------------
async function sha256(buffer) {
  const digest = new Uint8Array(await crypto.subtle.digest("SHA-256", buffer));
  let text = "";
  for (const byte of digest) text += String.fromCharCode(byte);
  return "sha256-" + btoa(text);
}

/** The response again if its bytes are the manifest's, else null (it is read: use what this returns).
 *  Its body is taken as a Blob, which for a stored response is a handle on the stored bytes, not a copy:
 *  the bytes are read once, to be hashed, and the response returned serves the same Blob as the
 *  stored one would. (Hashing a clone teed the body, so that the response served afterwards streamed
 *  through this worker's script: a revisit's snapshot read ended 0.25-0.4 s later.) */
async function genuine(response, entry) {
  try {
    const blob = await response.blob();
    if (!entry.hashes.includes(await sha256(await blob.arrayBuffer()))) return null;
    const { status, statusText, headers } = response;
    return new Response(blob, { status, statusText, headers });
  } catch {
    return null;
  }
}

// ---- What is stored ------------------------------------------------------------------
const verified = new Set(); // URLs verified in this worker's life (the copy's own bookkeeping)
let copying = null; // the copy in progress, shared by every page that asks
let stopped = false; // declined: the lanes stop after their current file

async function wanted() {
  return Boolean(await (await caches.open(STATE)).match(WANTED));
}

async function sealed() {
  const seal = await (await caches.open(CACHE)).match(SEAL);
  if (!seal) return false;
  try {
    const { version, count } = await seal.json();
    if (version !== VERSION || count !== ENTRIES.size) return false;
  } catch {
    return false;
  }
  const keys = (await (await caches.open(CACHE)).keys()).filter((r) => ENTRIES.has(r.url));
  return keys.length === ENTRIES.size;
}

async function unseal() {
  await (await caches.open(CACHE)).delete(SEAL);
}

/** {state, files, total, bytes, totalBytes, wireBytes}: what this browser holds of this version. */
async function status() {
  const complete = await sealed();
  let files = 0;
  let bytes = 0;
  if (complete) [files, bytes] = [ENTRIES.size, TOTAL_BYTES];
  else {
    for (const url of verified) {
      files++;
      bytes += ENTRIES.get(url).storedSize;
    }
  }
  const state = complete ? "complete" : copying ? "copying" : "partial";
  return {
    type: "status", version: VERSION, state, wanted: await wanted(), files, total: ENTRIES.size, bytes,
    totalBytes: TOTAL_BYTES, wireBytes: WIRE_BYTES,
  };
}

async function broadcast(message) {
  for (const client of await sw.clients.matchAll({ includeUncontrolled: true })) client.postMessage(message);
}

// The memory snapshot travels gzip-compressed and is stored inflated, so later
// starts read it as is; the manifest lists both hashes.
const INFLATE = /\.snapshot\.gz$/;
function inflated(response) {
  if (typeof DecompressionStream !== "function") return response;
  const body = response.body.pipeThrough(new DecompressionStream("gzip"));
  return new Response(body, { headers: { "Content-Type": "application/octet-stream" } });
}

async function fetchChecked(url, entry, mode) {
  const request = new Request(url, { cache: mode, integrity: entry.integrity, mode: "same-origin" });
  const response = await fetch(request);
  if (!response.ok) throw new Error(`${entry.path}: HTTP ${response.status}`);
  return response;
}

/** The same file from an older version's cache, if it is still genuine (an update reuses it). */
async function fromOlder(url, entry) {
  for (const name of await caches.keys()) {
    if (!name.startsWith(PREFIX) || name === CACHE || name === STATE) continue;
    const old = await (await caches.open(name)).match(url);
    const same = old && (await genuine(old, entry));
    if (same) return same;
  }
  return null;
}

/** Store one file and verify what was stored. */
async function storeOne(cache, url, entry) {
  const older = await fromOlder(url, entry);
  const response = older
    || (await fetchChecked(url, entry, "default").catch(() => fetchChecked(url, entry, "no-cache")));
  await cache.put(url, !older && INFLATE.test(entry.path) ? inflated(response) : response);
  const stored = await cache.match(url);
  if (!stored || !(await genuine(stored, entry))) {
    await cache.delete(url);
    throw new Error(`${entry.path}: the stored copy does not match the manifest`);
  }
  verified.add(url);
}

/** Store and verify every file not verified yet; seal the cache when all are. */
async function copyAll() {
  const cache = await caches.open(CACHE);
  const have = new Set((await cache.keys()).map((r) => r.url));
  for (const [url, entry] of ENTRIES) {
    // Resume: what an earlier, interrupted copy stored counts once it verifies.
    if (!verified.has(url) && have.has(url)) {
      const stored = await cache.match(url);
      if (stored && (await genuine(stored, entry))) verified.add(url);
      else await cache.delete(url);
    }
  }
  const todo = [...ENTRIES].filter(([url]) => !verified.has(url));
  let next = 0;
  let lastReport = 0;
  const lane = async () => {
    while (next < todo.length && !stopped) {
      const [url, entry] = todo[next++];
      await storeOne(cache, url, entry);
      if (Date.now() - lastReport > 250) {
        lastReport = Date.now();
        broadcast({ ...(await status()), type: "progress" });
      }
    }
  };
  await Promise.all(Array.from({ length: LANES }, lane));
  if (stopped) throw new Error("declined");
  // Count and hashes: every manifest entry is in the cache and was verified.
  const keys = new Set((await cache.keys()).map((r) => r.url));
  const complete = [...ENTRIES.keys()].every((url) => keys.has(url) && verified.has(url));
  if (!complete) throw new Error("the copy is incomplete");
  await cache.put(SEAL, new Response(JSON.stringify({ version: VERSION, count: ENTRIES.size, bytes: TOTAL_BYTES })));
  for (const [url, entry] of LATER_ENTRIES) { // kept by the last version, or in the HTTP cache: no download
    if (await cache.match(url)) continue;
    const older = await fromOlder(url, entry);
    const had = older || (await fetchChecked(url, entry, "only-if-cached").catch(() => null));
    if (had) await keepLater(url, entry, had, !older);
  }
}

/** Keep a file of LATER (`raw`: as the host sends it, not yet inflated), if its bytes are the manifest's. */
async function keepLater(url, entry, response, raw = true) {
  const cache = await caches.open(CACHE);
  await cache.put(url, raw && INFLATE.test(entry.path) ? inflated(response) : response);
  const kept = await cache.match(url);
  if (!kept || !(await genuine(kept, entry))) await cache.delete(url);
}

/** A file of LATER: the stored copy while genuine, else the network's (kept when the copy is wanted). */
async function later(key, request, event) {
  const entry = LATER_ENTRIES.get(key);
  const hit = await (await caches.open(CACHE)).match(key);
  const same = hit && (await genuine(hit, entry));
  if (same) return same;
  const response = await fetch(request);
  if (response.ok && (await wanted())) event.waitUntil(keepLater(key, entry, response.clone()).catch(() => {}));
  return response;
}

function copy() {
  stopped = false;
  copying ||= copyAll()
    .then(async () => {
      await sw.clients.claim();
      broadcast(await status());
    })
    .catch(async (err) => {
      broadcast({ type: "store-failed", message: String(err?.message || err) });
      throw err;
    })
    .finally(() => {
      copying = null;
    });
  return copying;
}

/** After any event: if the learner wants the copy and it is not complete, go on with it. */
async function resume() {
  if (copying || !(await wanted()) || (await sealed())) return;
  await copy().catch(() => {});
}

async function decline() {
  stopped = true;
  await (await caches.open(STATE)).delete(WANTED);
  await copying?.catch(() => {});
  await caches.delete(CACHE);
  verified.clear();
}

// ---- Life cycle ---------------------------------------------------------------------
sw.addEventListener("install", (event) => event.waitUntil((async () => {
  // An update of a stored site: whole before it takes over. Otherwise nothing yet.
  if (sw.registration.active && (await wanted())) await copyAll();
  else await sw.skipWaiting();
})()));

sw.addEventListener("activate", (event) => event.waitUntil((async () => {
  for (const name of await caches.keys()) {
    if (name.startsWith(PREFIX) && name !== CACHE && name !== STATE) await caches.delete(name);
  }
  if (await sealed()) await sw.clients.claim();
})()));

sw.addEventListener("message", (event) => {
  const reply = async (message) => event.source?.postMessage(await message);
  const type = event.data?.type;
  if (type === "activate-update") sw.skipWaiting();
  else if (type === "status") event.waitUntil(reply(status()).then(resume));
  else if (type === "store") {
    event.waitUntil((async () => {
      await (await caches.open(STATE)).put(WANTED, new Response("yes"));
      await copy().catch(() => {});
    })());
  } else if (type === "decline") event.waitUntil(decline().then(() => reply(status())));
});

// ---- Serving --------------------------------------------------------------------------
function isolate(response) {
  const unreadable = response?.type === "opaque" || response?.type === "opaqueredirect" || response?.status === 0;
  if (!response || unreadable) return response;
  const headers = new Headers(response.headers);
  for (const [name, value] of Object.entries(ISOLATION)) headers.set(name, value);
  return new Response(response.body, { status: response.status, statusText: response.statusText, headers });
}

/** The URL in `entries` (the manifest's, or LATER's) a request stands for, or null. */
function cacheKey(url, entries = ENTRIES) {
  url = new URL(url);
  url.search = "";
  url.hash = "";
  if (url.pathname.endsWith("/index.html")) url.pathname = url.pathname.slice(0, -"index.html".length);
  return entries.has(url.href) ? url.href : null;
}

/** The stored response for `key` if it is genuine; a tampered one is deleted (and the seal with it). */
async function stored(key) {
  const cache = await caches.open(CACHE);
  const response = await cache.match(key);
  if (!response) return null;
  const same = await genuine(response, ENTRIES.get(key));
  if (same) return same;
  verified.delete(key);
  await cache.delete(key);
  await unseal();
  return null;
}

function refused(path) {
  const text = `<!doctype html><meta charset="utf-8"><title>Not available offline</title>
<p>This page (<code>${path.replace(/[<&]/g, "")}</code>) is not stored in this browser, or its stored copy was
damaged and was not used, and the network cannot be reached. Connect to the network and reload: the workbook
then stores it again.</p>`;
  return new Response(text,
    { status: 503, statusText: "Service Unavailable", headers: { "Content-Type": "text/html; charset=utf-8" } });
}

const forDocument = (request) =>
  request.destination === "document" || request.destination === "worker" || request.mode === "navigate";

async function respond(request, event) {
  const key = cacheKey(request.url);
  if (new URL(request.url).pathname === new URL(SITEMAP).pathname) return sitemap();
  if (key === NOT_FOUND && request.mode === "navigate") return (await notFound()) || isolate(await fetch(request));
  const kept = key ? null : cacheKey(request.url, LATER_ENTRIES);
  if (kept) return later(kept, request, event);
  if (key) {
    const hit = await stored(key);
    // Only documents and workers need the isolation headers; everything else is
    // returned with the headers it was stored with.
    if (hit) return forDocument(request) ? isolate(hit) : hit;
    const damagedOrMissing = verified.size > 0 || (await wanted());
    try {
      const response = await fetch(request);
      if (damagedOrMissing) event.waitUntil(resume()); // put back what is missing or was damaged
      return forDocument(request) ? isolate(response) : response;
    } catch (err) {
      if (request.mode === "navigate") return refused(ENTRIES.get(key).path);
      throw err;
    }
  }
  if (request.mode === "navigate") {
    // "chapters/x" for "chapters/x/": send the browser to the real address.
    const url = new URL(request.url);
    url.pathname += "/";
    url.search = "";
    if (ENTRIES.has(url.href)) return Response.redirect(url.href, 301);
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

/** The stored 404 page, its <base> set to this scope so its relative URLs work at any depth. */
async function notFound() {
  const cached = await stored(NOT_FOUND);
  if (!cached) return null;
  const html = (await cached.text()).replace(/<base href="[^"]*">/, `<base href="${SCOPE}">`);
  const headers = new Headers(cached.headers);
  headers.delete("Content-Length");
  return isolate(new Response(html, { status: 404, statusText: "Not Found", headers }));
}

/** The site's pages as a sitemap for this scope (what instant navigation needs: each page's <loc>). */
function sitemap() {
  const pages = [...ENTRIES.keys()].filter((url) => url.endsWith("/"));
  const body = `<?xml version="1.0" encoding="UTF-8"?>\n<urlset xmlns="http://www.sitemaps.org/schemas/sitemap/0.9">\n${pages
    .map((url) => `<url><loc>${url}</loc></url>`)
    .join("\n")}\n</urlset>\n`;
  return new Response(body, { headers: { "Content-Type": "application/xml" } });
}

sw.addEventListener("fetch", (event) => {
  const { request } = event;
  if (request.method !== "GET" || !request.url.startsWith(SCOPE)) return;
  if (request.cache === "only-if-cached" && request.mode !== "same-origin") return;
  event.respondWith(respond(request, event));
  if (request.mode === "navigate") event.waitUntil(resume()); // a navigation during the copy continues it
});
