"""The expression reader behind :mod:`workbook.answers` and :mod:`workbook.formula`.

A learner's text goes through four small steps, one module each:

- :mod:`.grammar`: what an answer may contain (functions, constants, Greek
  names, the limits) and :class:`~.grammar.Grammar`, which says what a name
  means in one kind of answer; also :class:`~.grammar.InvalidAnswer`.
- :mod:`.tokens`: text to tokens (unicode spellings unified, names split and
  classified, commas in numbers explained).
- :mod:`.parsing`: tokens to a tree of tuples, by recursive descent, with the
  limits on nesting and size checked on the way.
- :mod:`.evaluate`: a tree to a value in SI with its dimension.

Nothing here calls ``eval``. The public entry points are
:func:`workbook.answers.parse_answer`, :func:`workbook.answers.parse_quantity`
and :func:`workbook.formula.parse_formula`.
"""
