// What the workers find in their global scope without importing it (declarations only).
/** File name -> bytes of the runtime's files, defined by the bundler (scripts/bundle.mjs). */
declare const BOOT_SIZES: Record<string, number> | undefined;
/** File name -> "sha256-..." of the bytes the service worker stores for it, defined by the bundler (scripts/bundle.mjs). */
declare const STORED_INTEGRITY: Record<string, string> | undefined;
/** Pyodide's loader, from pyodide.js (loaded with importScripts). */
declare function loadPyodide(options: object): Promise<any>;
interface WorkerGlobalScope {
  /** The sandbox's settings, set by the script sandbox-client.js starts it with. */
  WB_SANDBOX?: SandboxSettings;
}
/** What sandbox-client.js starts the sandbox with: where Pyodide is, the link's speed (bytes per ms), whether
 *  the first message brings the grader's compiled WebAssembly. */
interface SandboxSettings { indexURL: string; linkSpeed?: number | null; module?: boolean }
