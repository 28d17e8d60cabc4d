"""Time bringing a robot in: draft its description, count its lines, drive its report card.

Run: ``.venv/bin/python benchmarks/robot_draft_bench.py``. For each example in
``examples/robots/`` (and each built-in robot's URDF) prints the draft's time [s], the
description's lines of code (comments and blank lines not counted), and the check's time
[s] and verdict. The issue's goal: at most 40 lines, checked, in under 30 minutes of work.
PyCRAM, the reference, needs a robot class of about 150 lines and has no drafting tool.
"""

from __future__ import annotations

import importlib.util
import time
import warnings
from pathlib import Path

from robocram.robot_check import check_robot, description_from
from robocram.robots import draft_description
from robocram.robots.builtin import builtin_description

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "robots"


def code_lines(text: str) -> int:
    """Lines that are neither blank nor comments, outside the module docstring."""
    body = text.split('"""', 2)[-1] if text.startswith('"""') else text
    return sum(1 for line in body.splitlines() if line.strip() and not line.strip().startswith("#"))


def _urdf_of(path: Path) -> Path:
    spec = importlib.util.spec_from_file_location(f"bench_{path.stem}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return Path(module.URDF)


def bench_example(path: Path) -> None:
    """Print draft time, lines and check time of one edited example."""
    start = time.perf_counter()
    draft_description(_urdf_of(path)).source(path)
    drafted = time.perf_counter() - start
    start = time.perf_counter()
    card = check_robot(description_from(str(path)))
    checked = time.perf_counter() - start
    verdict = "all pass" if card.passed else f"{len(card.failures())} FAIL"
    lines = code_lines(path.read_text(encoding="utf-8"))
    print(
        f"{path.stem:<12} draft {drafted:6.2f} s  {lines:4d} lines of code  "
        f"check {checked:6.1f} s ({len(card.results)} checks, {verdict})"
    )


def bench_builtin(name: str) -> None:
    """Print the draft time and its lines for a built-in robot's URDF."""
    start = time.perf_counter()
    text = draft_description(builtin_description(name).urdf).source()
    seconds = time.perf_counter() - start
    print(f"{name:<12} draft {seconds:6.2f} s  {code_lines(text):4d} lines of code")


def main() -> None:
    """Bench every example and built-in robot."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for path in sorted(EXAMPLES.glob("*.py")):
            bench_example(path)
        for name in ("pr2", "hsrb", "boxy"):
            bench_builtin(name)


if __name__ == "__main__":
    main()
