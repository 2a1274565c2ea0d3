// Bundle the page's JavaScript with esbuild: docs/assets/js -> docs/assets/dist.
// main.js is an ES module with code splitting (the CodeMirror editor loads only
// on pages with a Build exercise); worker.js is a classic worker script.
import { build } from "esbuild";
import { createHash } from "node:crypto";
import { readFileSync, readdirSync, rmSync, statSync } from "node:fs";
import { gunzipSync } from "node:zlib";

// Start clean: stale hashed chunks would otherwise ship (and be precached for offline use).
rmSync("docs/assets/dist", { recursive: true, force: true });

const common = { bundle: true, minify: true, sourcemap: true, target: ["es2020"], logLevel: "warning", legalComments: "linked" };

await build({
  ...common,
  entryPoints: { workbook: "docs/assets/js/main.js" },
  outdir: "docs/assets/dist",
  format: "esm",
  splitting: true,
  chunkNames: "chunks/[name]-[hash]",
});
// The runtime files' sizes, for the boot's progress bar (docs/assets/js/boot-meter.js): real bytes, known at build time.
const VENDOR = "docs/assets/vendor/pyodide";
const sizes = Object.fromEntries(readdirSync(VENDOR).map((name) => [name, statSync(`${VENDOR}/${name}`).size]));
// The sha256 of what the service worker stores for the two largest files of a start, which the grader's
// worker reads from that copy itself (docs/assets/js/stored-copy.js): the same hashes as the service
// worker's manifest (docs/hooks/offline.py), the snapshot's of its inflated bytes, as it is stored.
const integrity = (bytes) => "sha256-" + createHash("sha256").update(bytes).digest("base64");
const stored = {
  "pyodide.asm.wasm": integrity(readFileSync(`${VENDOR}/pyodide.asm.wasm`)),
  "workbook.snapshot.gz": integrity(gunzipSync(readFileSync(`${VENDOR}/workbook.snapshot.gz`))),
};
await build({
  ...common,
  entryPoints: { worker: "docs/assets/js/worker.js" },
  outdir: "docs/assets/dist",
  format: "iife",
  define: { BOOT_SIZES: JSON.stringify(sizes), STORED_INTEGRITY: JSON.stringify(stored) },
});
// The worker that stands in for the theme's search worker until search is wanted
// (docs/assets/js/search-worker.js, docs/hooks/search_worker.py): a classic worker script too.
await build({ ...common, entryPoints: { "search-worker": "docs/assets/js/search-worker.js" }, outdir: "docs/assets/dist", format: "iife" });
// The SCORM packages' launcher pages (scripts/scorm/launch.html.j2, docs/assets/js/lms/launch.js): a classic script.
await build({ ...common, entryPoints: { "lms-launch": "docs/assets/js/lms/launcher.js" }, outdir: "docs/assets/dist", format: "iife" });
// The sandbox that runs learner code (docs/assets/js/sandbox.js): a classic worker script of its own.
await build({
  ...common,
  entryPoints: { sandbox: "docs/assets/js/sandbox.js" },
  outdir: "docs/assets/dist",
  format: "iife",
  define: { BOOT_SIZES: JSON.stringify(sizes) },
});
