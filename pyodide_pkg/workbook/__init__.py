"""Robotics Math Workbook: reference math, exercise bank and graders.

Nothing heavy happens at import time: chapters are imported on first use.
"""

__version__ = "0.1.0"
