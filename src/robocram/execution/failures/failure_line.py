"""A failure on one short line: its type and what went wrong, without the data dump.

``str(failure)`` of a plan failure ends with its fields, context and hint (designators,
poses, commands: often 500 characters), which traces keep. Task trees and batch summaries
show :func:`failure_line` instead. It works on the stored text, so a tree read back from a
trace shortens the same way as a live one, and it masks coordinate tuples, so that tries
that failed the same way at different poses read the same and can be counted together.

>>> failure_line("NavigationPoseUnreachable", "pr2 at (-0.690, -0.955, -1.034) would "
...     "collide with ['kitchen/table_top'] (target=Pose(...), colliding=[...]) [command=x]")
"NavigationPoseUnreachable: pr2 at (…) would collide with ['kitchen/table_top']"
"""

from __future__ import annotations

import re

LINE_WIDTH = 160  # [characters] of a failure line, its type included

_NUMBER = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"
_COORDINATES = re.compile(rf"\(\s*{_NUMBER}(?:\s*,\s*{_NUMBER})+\s*,?\s*\)")
_DATA_DUMP = re.compile(r" [(\[][a-z_]\w*=")  # PlanFailure's "(field=...)" and "[context=...]"


def failure_line(failure_type: str | None, text: str | None, width: int = LINE_WIDTH) -> str:
    """``Type: what went wrong`` in at most ``width`` characters, fields and hint left out."""
    head = (text or "").strip().split("\n", 1)[0]
    dump = _DATA_DUMP.search(head)
    if dump is not None:
        head = head[: dump.start()]
    head = _COORDINATES.sub("(…)", head).rstrip(" ;:")
    line = f"{failure_type or 'failure'}: {head}" if head else failure_type or "failure"
    return line if len(line) <= width else line[: width - 1].rstrip() + "…"
