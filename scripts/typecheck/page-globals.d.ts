// What the page's modules find on `window` without importing it (declarations only: the type
// checker's view of names that come from elsewhere; nothing here is built or shipped).
interface Window {
  /** Forms submitted before their widget's script was ready, held by main.html (exercise.js checks them). */
  __workbookSubmits?: HTMLFormElement[];
  /** The site root, set by docs/overrides/main.html before the bundle loads. */
  __workbookBase?: string;
  /** The grader's worker started early by main.html, with the messages it sent before main.js ran. */
  __workbookEarly?: { worker: Worker; messages: MessageEvent[]; started: number } | null;
  /** For tests and tools: the page's runtime, progress and friends (main.js, sandbox-client.js). */
  workbook?: any;
  /** mkdocs-material's stream of pages (the first and each instant navigation). */
  document$?: { subscribe(next: () => void): unknown };
  /** KaTeX, vendored as a classic script. */
  katex?: { render(tex: string, element: HTMLElement, options?: object): void };
}

interface Navigator {
  /** The Network Information API, where the browser has it (offline.js: metered or slow links). */
  connection?: { saveData?: boolean; type?: string; effectiveType?: string };
}
