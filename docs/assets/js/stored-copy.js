// The service worker's stored copy of a runtime file, read by the worker itself.
//
// The service worker checks every stored file against its manifest's sha256 before it serves it
// (sw.js, genuine()). On a revisit that put the two largest files of the start, the WebAssembly
// (10 MB) and the memory snapshot (15.5 MB), through the service worker's one thread, while it
// was also serving the page: the snapshot came 106-216 ms after a direct read would have
// (docs/decisions/0045). So the worker reads those two from Cache Storage itself and checks
// them here, against the same hashes: scripts/bundle.mjs writes the build's into
// STORED_INTEGRITY (the snapshot's is its inflated bytes', as the service worker stores it). A
// copy that is not the build's (another version's, or damaged, or planted) is never used: the
// caller then fetches the file through the service worker, which repairs its copy.

/* global STORED_INTEGRITY */
const INTEGRITY = typeof STORED_INTEGRITY === "object" ? STORED_INTEGRITY : {};

/** The stored response for `url` in any of the origin's caches, or null (none, or no Cache Storage). */
export async function storedResponse(url) {
  try {
    return (await self.caches?.match(url)) || null;
  } catch {
    return null; // no Cache Storage here (an insecure origin)
  }
}

async function sha256(bytes) {
  const digest = new Uint8Array(await crypto.subtle.digest("SHA-256", bytes));
  let text = "";
  for (const byte of digest) text += String.fromCharCode(byte);
  return "sha256-" + btoa(text);
}

/** The bytes of a stored `response` for the file `name` if they are the build's, else null (no response,
 *  no hash known for the file, or other bytes). */
export async function storedBytes(response, name) {
  const expected = INTEGRITY[name];
  if (!response || !expected) return null;
  try {
    const bytes = new Uint8Array(await response.arrayBuffer());
    return (await sha256(bytes)) === expected ? bytes : null;
  } catch {
    return null;
  }
}
