"""Write ``tests/suite_durations.json`` from a suite run's JUnit XML, so xdist deals out the
longest groups and tests first (tests/conftest.py).

    pytest -n 2 --dist loadgroup --no-loadscope-reorder --junitxml=/tmp/suite.xml
    python tools/suite_durations.py /tmp/suite.xml

Only tests of at least ``--least`` seconds are kept (the rest count as the conftest's
``UNMEASURED``): the file stays small and its order does not churn with the machine's load.
"""

from __future__ import annotations

import argparse
import json
import xml.etree.ElementTree as ElementTree
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "tests" / "suite_durations.json"


def node_id(classname: str, name: str) -> str | None:
    """The pytest node id JUnit's ``classname`` and ``name`` were made from (the module's
    path is the longest dotted prefix naming a file; the rest are classes), without the
    ``@group`` xdist appends; None for a file that is not there."""
    if name.rfind("@") > name.rfind("]"):
        name = name.rpartition("@")[0]
    parts = classname.split(".")
    for cut in range(len(parts), 0, -1):
        path = "/".join(parts[:cut]) + ".py"
        if (ROOT / path).is_file():
            return "::".join([path, *parts[cut:], name])
    return None


def durations(xml_files: list[Path]) -> dict[str, float]:
    """Seconds per node id (set-up, call and tear-down, as JUnit reports them)."""
    found: dict[str, float] = {}
    for xml_file in xml_files:
        for case in ElementTree.parse(xml_file).iter("testcase"):
            nodeid = node_id(case.get("classname", ""), case.get("name", ""))
            if nodeid is not None:
                found[nodeid] = max(found.get(nodeid, 0.0), float(case.get("time", "0")))
    return found


def main() -> None:
    parser = argparse.ArgumentParser(description="tests/suite_durations.json from JUnit XML")
    parser.add_argument("xml", nargs="+", type=Path, help="JUnit XML of a suite run")
    parser.add_argument("--least", type=float, default=0.3, help="[s] keep tests this long")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args()
    kept = {
        nodeid: round(seconds, 1)
        for nodeid, seconds in sorted(durations(args.xml).items())
        if seconds >= args.least
    }
    args.out.write_text(json.dumps(kept, indent=0) + "\n")
    print(f"{len(kept)} tests of at least {args.least} s, {sum(kept.values()):.0f} s in all")


if __name__ == "__main__":
    main()
