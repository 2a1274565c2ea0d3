"""What runs a learner's Build code: standard library only, and nothing of the grader.

In the page this package is the only Python code of the *sandbox*, a Web Worker
of its own that holds no keys, no reference implementations and no ``workbook``
package (``docs/assets/js/sandbox.js``). It runs the learner's function on the
cases the grader chose and reports what came back, as plain JSON; the grader
(``workbook.kinds.build``) compares those outputs with its own and writes every
verdict. Natively the grader runs :func:`runner.run` in its own process.

* :mod:`.harness`: the drivers that exercise a learner's function on one case
  (``call`` calls it; closed-loop drivers run it over a trajectory). The grader
  runs its reference through the same driver.
* :mod:`.runner`: compile, load, drive every case, report; ``print`` captured.
* :mod:`.restore`: put back what a run changed in loaded modules.
* :mod:`.lazy_stdlib`: the rest of the standard library, mounted on first use (in both
  workers: the grader's Python holds this package too).

It must import nothing from ``workbook`` (``tests/unit/test_sandbox_package.py``).
"""
