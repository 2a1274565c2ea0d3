// Which modules of the standard library the page needs before and while grading.
//
// Node boots the vendored Pyodide with the official standard library, imports
// the grading package from its sources (as the page will: from the core zip,
// not through the package loader) and drives every request the page sends:
// a grade of each exercise with good, bad and unreadable answers, Build runs
// that pass, fail, raise and do not compile (run in process, as the sandbox runs them), draws, splits, readings and every
// figure. The modules then loaded from the standard library are the core
// (scripts/split_stdlib.py); the rest is fetched on first use
// (workbook_sandbox/lazy_stdlib.py).
//
// Usage: node scripts/stdlib_probe.mjs [vendor-dir]  -> build/stdlib-used.json
import { mkdirSync, readdirSync, readFileSync, statSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import path from "node:path";
import { fileURLToPath } from "node:url";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");
const vendor = path.resolve(process.argv[2] || path.join(root, "docs/assets/vendor/pyodide")) + "/";
const require = createRequire(import.meta.url);
const { loadPyodide } = require(vendor + "pyodide.js");

const stdLibURL = path.join(root, "build/stdlib/python_stdlib.zip"); // the official one (scripts/vendor.py)
const py = await loadPyodide({ indexURL: vendor, stdLibURL, stdout: () => {}, stderr: () => {} });
const pkg = path.join(root, "pyodide_pkg");
function copyTree(dir, into) {
  py.FS.mkdirTree(into);
  for (const name of readdirSync(dir)) {
    const from = path.join(dir, name);
    if (statSync(from).isDirectory()) {
      if (name !== "__pycache__") copyTree(from, `${into}/${name}`);
    } else if (/\.(py|json)$/.test(name)) py.FS.writeFile(`${into}/${name}`, readFileSync(from));
  }
}
for (const name of ["workbook", "workbook_sandbox"]) copyTree(path.join(pkg, name), `/probe/${name}`);

const PROBE = `
import importlib, json, pkgutil, sys
sys.path.insert(0, "/probe")
import workbook
for info in pkgutil.walk_packages(workbook.__path__, "workbook."):
    importlib.import_module(info.name)
from workbook import api, bank, figures

def ask(**request):
    api.handle(json.dumps(request))

for ex in bank.all_exercises():
    if ex.op == "run":  # the page asks for cases and a judgement; the sandbox runs the code (runner, here in process)
        for code in (ex.starter, ex.solution, "def f(:\\n    pass\\n", "def %s(*a):\\n    return 1/0\\n" % ex.function,
                     "import no_such_module\\n", "x = 1\\n", "print('hi')\\n", "def %s(*a):\\n    return 5\\n" % ex.function):
            ask(op="cases", exercise=ex.id, code=code)
            ex.check(code)
        ask(op="judge", exercise=ex.id, outputs="{}")
        continue
    for answer in ("1", "", "abc", "sqrt(2)/2", "45°", "1 m", "2,5", "1e999", [["1"]], ["a"], "a"):
        ask(op=ex.op, exercise=ex.id, answer=answer)
    if ex.kind == "derive":
        for n in (0, 7):
            ask(op="draw", exercise=ex.id, variant=n, texts={"prompt": "", "title": "", "hint": "", "solution": "x"})
            ask(op="grade", exercise=ex.id, variant=n, answer=ex.variant(n).worked_text())
        ask(op="split", exercise=ex.id, text="[[1, 2], [3, 4]]")
        ask(op="read", exercise=ex.id, answer="L1*cos(theta1)")
for name in figures.names():
    ask(op="figure", figure=name, params={})
from workbook_sandbox import lazy_stdlib
lazy_stdlib.install("probe")
from pyodide.code import find_imports
find_imports("import numpy\\nx = 1")
json.dumps(sorted({m.__file__.split(".zip/", 1)[1] for m in list(sys.modules.values())
                   if ".zip/" in (getattr(m, "__file__", None) or "")} - {"workbook"}))
`;
const used = JSON.parse(py.runPython(PROBE));
mkdirSync(path.join(root, "build"), { recursive: true });
writeFileSync(path.join(root, "build/stdlib-used.json"), JSON.stringify(used, null, 1) + "\n");
console.log(`stdlib probe: ${used.length} files of the standard library used`);
