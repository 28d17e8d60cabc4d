"""ISO conformance: run benchmarks/iso_cases.pl on robocram.logic and on SWI-Prolog.

The cases (written for robocram from the ISO standard's rules, not copied from a suite)
check answers and the error term of each failing built-in call. The script prints how
many pass on each system and lists the cases where robocram is wrong.
Usage: python benchmarks/conformance_bench.py [--verbose]
"""

from __future__ import annotations

import argparse
import contextlib
import io
import re
import shutil
import subprocess
from pathlib import Path

from robocram.logic import KnowledgeBase

CASES = Path(__file__).with_name("iso_cases.pl")
_LINE = re.compile(r"^(\d+) (pass|fail) (.*)$", re.M)


def ours() -> dict[int, tuple[str, str]]:
    """Case id -> (pass/fail, result) on robocram.logic."""
    kb = KnowledgeBase()
    kb.consult(CASES.read_text(encoding="utf-8"))
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        kb.holds("iso_run")
    return {int(m[1]): (m[2], m[3]) for m in _LINE.finditer(out.getvalue())}


def swi() -> dict[int, tuple[str, str]]:
    """The same on SWI-Prolog (empty when swipl is not installed)."""
    if shutil.which("swipl") is None:
        return {}
    result = subprocess.run(
        ["swipl", "-g", "iso_run", "-t", "halt", str(CASES)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    return {int(m[1]): (m[2], m[3]) for m in _LINE.finditer(result.stdout)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--verbose", action="store_true", help="list every failing case")
    args = parser.parse_args()
    total = len(re.findall(r"^case\(", CASES.read_text(encoding="utf-8"), re.M))
    mine, theirs = ours(), swi()
    for name, res in (("robocram", mine), ("SWI-Prolog", theirs)):
        if res or name == "robocram":
            passed = sum(1 for s, _ in res.values() if s == "pass")
            print(f"{name:<12} {passed:>4} / {total} cases pass")
    wrong = sorted(i for i in range(1, total + 200) if i in mine and mine[i][0] == "fail")
    missing = total - len(mine)
    if missing:
        print(f"robocram printed no line for {missing} cases (the run stopped early)")
    for i in wrong if args.verbose else wrong[:10]:
        print(f"  case {i}: robocram gave {mine[i][1]}")


if __name__ == "__main__":
    main()
