// The steps of a Python worker's start, shared by the workers that report them
// (boot.js, worker.js, sandbox.js) and the page that shows them (loading.js).
//
// A start reports {phase, loaded, total, step}: `phase` is the contract's
// bootPhase (download, start, ready); `step` says what the worker is doing now:
// "download" while the runtime's files arrive, then, once every byte is in,
// "compile" (WebAssembly), "restore" (from the memory snapshot) or "boot" (a
// plain start of the interpreter), then "import" (the worker's own package).
export const BOOT_STEP = Object.freeze({
  download: "download",
  compile: "compile",
  restore: "restore",
  boot: "boot",
  import: "import",
});

/** The order the steps come in (a later step never gives way to an earlier one). @type {readonly string[]} */
export const STEP_ORDER = Object.freeze([BOOT_STEP.download, BOOT_STEP.compile, BOOT_STEP.restore, BOOT_STEP.boot,
  BOOT_STEP.import]);
