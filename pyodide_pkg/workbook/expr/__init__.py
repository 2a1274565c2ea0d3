"""The one reader of learners' text: numbers, expressions, formulas, vectors and matrices.

A learner's text goes through small steps, one module each:

- :mod:`.grammar`: what an answer may contain (functions, constants, Greek
  names, the limits) and :class:`~.grammar.Grammar`, which says what a name
  means in one kind of answer; also :class:`InvalidAnswer`.
- :mod:`.latex_input` and :mod:`.tokens`: text to tokens (LaTeX rewritten,
  look-alike characters unified, names split and classified).
- :mod:`.parsing`: tokens to a tree of tuples, by recursive descent, with the
  limits on nesting and size checked on the way.
- The tree walkers: :mod:`.evaluate` (a value with its dimension),
  :mod:`.compile` (a fast function of a formula's variables),
  :mod:`.latex_output` (how the page shows what was read) and :mod:`.degrees`
  (``cos(90)`` read with 90 in degrees).
- :mod:`.quantity` (a number in the unit asked, with its typed precision),
  :mod:`.precision`, :mod:`.formula` (a formula over named variables) and
  :mod:`.layout` (a pasted vector or matrix split into entries).

Nothing here calls ``eval``. The answer kinds (:mod:`workbook.answer_kinds`)
read through this package only.
"""

from .formula import Formula, parse_formula
from .grammar import MAX_LENGTH, InvalidAnswer
from .layout import component_key, is_one_value, named_entry, place_by_name, split_matrix
from .quantity import Answer, Reading, parse_answer, parse_quantity, read_quantity

__all__ = [
    "MAX_LENGTH", "Answer", "Formula", "InvalidAnswer", "Reading", "component_key", "is_one_value",
    "named_entry", "parse_answer", "parse_formula", "parse_quantity", "place_by_name", "read_quantity",
    "split_matrix",
]
