"""Which zoo drafts a change alters: every URDF of the zoo's corpus drafted by two source
trees, the written modules compared byte for byte.

Run: ``.venv/bin/python benchmarks/draft_diff.py BASE_SRC HEAD_SRC [--out DIR] [--only NAME ...]``
(``BASE_SRC``, ``HEAD_SRC``: the ``src`` folders of, say, main and a branch). Each tree
drafts in a process of its own (its ``src`` first on the path), as ``robot_zoo.py`` does;
the table lists per robot ``same``, ``changed`` (with the changed lines' count) or the
draft's error, and a robot's unified diff is written next to the drafts.
"""

from __future__ import annotations

import argparse
import difflib
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent

_DRAFT = """
import sys, warnings
warnings.simplefilter("ignore")
sys.path.insert(0, {here!r})
from pathlib import Path
import robot_zoo
out = Path({out!r})
only = {only!r}
for robot in robot_zoo.CORPUS:
    if not robot.source.endswith(".urdf") or (only and robot.name not in only):
        continue
    try:
        robot_zoo._draft(robot, out)
    except Exception as err:  # noqa: BLE001 - a draft's failure is a row of the table
        (out / f"{{robot.name}}.error").write_text(f"{{type(err).__name__}}: {{err}}", "utf-8")
"""


def draft_all(src: Path, out: Path, only: list[str]) -> None:
    """Every URDF robot of the corpus drafted by the tree ``src`` into ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, PYTHONPATH=str(src.resolve()))
    code = _DRAFT.format(here=str(HERE), out=str(out), only=only)
    subprocess.run([sys.executable, "-c", code], env=env, check=True)


def compare(base: Path, head: Path) -> list[tuple[str, str]]:
    """Per robot drafted on either side: ``same``, ``changed (N lines)`` or an error."""
    rows: list[tuple[str, str]] = []
    names = sorted({p.stem for side in (base, head) for p in side.iterdir()})
    for name in names:
        old, new = base / f"{name}.py", head / f"{name}.py"
        if not (old.is_file() and new.is_file()):
            errors = [(p / f"{name}.error") for p in (base, head)]
            rows.append(
                (name, "error: " + " | ".join(e.read_text("utf-8") for e in errors if e.is_file()))
            )
            continue
        if old.read_bytes() == new.read_bytes():
            rows.append((name, "same"))
            continue
        diff = list(
            difflib.unified_diff(
                old.read_text("utf-8").splitlines(),
                new.read_text("utf-8").splitlines(),
                str(old),
                str(new),
                lineterm="",
            )
        )
        (head.parent / f"{name}.diff").write_text("\n".join(diff) + "\n", "utf-8")
        changed = sum(1 for line in diff if line[:1] in "+-" and line[:3] not in ("+++", "---"))
        rows.append((name, f"changed ({changed} lines)"))
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", type=Path, help="the src folder drafting the reference")
    parser.add_argument("head", type=Path, help="the src folder whose drafts are compared")
    parser.add_argument("--out", type=Path, default=HERE.parent / "out" / "draft_diff")
    parser.add_argument("--only", nargs="*", default=[], help="robot names to draft")
    args = parser.parse_args(argv)
    base, head = args.out / "base", args.out / "head"
    draft_all(args.base, base, args.only)
    draft_all(args.head, head, args.only)
    rows = compare(base, head)
    width = max(len(name) for name, _ in rows)
    for name, verdict in rows:
        print(f"{name:<{width}}  {verdict}")
    changed = [name for name, verdict in rows if verdict != "same"]
    print(f"{len(rows) - len(changed)}/{len(rows)} drafts the same; changed: {changed or 'none'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
