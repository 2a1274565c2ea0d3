// ESLint (flat config) over the page's JavaScript: `make lint` runs it with --max-warnings 0.
// The recommended rules catch real mistakes (undefined names, unused variables, unreachable
// code, duplicate keys); nothing is switched off. Each file gets the globals its context
// really has: the page's modules a window's, the grader's, the sandbox's and the search's workers (and the
// boot module they share) a dedicated worker's, sw.js a service worker's (a classic script
// that docs/hooks/offline.py fills in). The page-side tests in tests/js (Node's runner) get the same rules
// and Node's globals.
import js from "@eslint/js";
import globals from "globals";

const WORKERS = ["docs/assets/js/worker.js", "docs/assets/js/sandbox.js", "docs/assets/js/boot.js",
  "docs/assets/js/search-worker.js"];
const SERVICE_WORKER = "docs/assets/js/sw.js";

export default [
  { linterOptions: { reportUnusedDisableDirectives: "error" } },
  { ...js.configs.recommended, files: ["docs/assets/js/**/*.js"] },
  {
    files: ["docs/assets/js/**/*.js"],
    ignores: [...WORKERS, SERVICE_WORKER],
    languageOptions: { sourceType: "module", globals: globals.browser },
  },
  {
    files: WORKERS,
    languageOptions: { sourceType: "module", globals: globals.worker },
  },
  {
    files: [SERVICE_WORKER],
    languageOptions: {
      sourceType: "script",
      globals: {
        ...globals.serviceworker, __WB_VERSION__: "readonly", __WB_FILES__: "readonly", __WB_WIRE_BYTES__: "readonly",
        __WB_LATER__: "readonly",
      },
    },
  },
  {
    ...js.configs.recommended,
    files: ["tests/js/**/*.mjs"],
    languageOptions: { sourceType: "module", globals: globals.node },
  },
  // Lines of at most 120 characters, comments and strings included (URLs excepted).
  { files: ["docs/assets/js/**/*.js", "tests/js/**/*.mjs"], rules: { "max-len": ["error", { code: 120, ignoreUrls: true }] } },
];
