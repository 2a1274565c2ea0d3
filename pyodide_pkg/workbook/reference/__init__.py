"""Reference implementations of the workbook's math, one module per topic.

Pure Python (lists of floats), so they import fast in the browser; every
function carries a doctest taken from the workbook's own numbers.
"""
