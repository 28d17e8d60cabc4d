"""Time loading built-in robots: parse and check, write URDF, load the written URDF in PyBullet.

Run: ``.venv/bin/python benchmarks/robots_load_bench.py [repeats]``. Prints milliseconds.
``load+check`` includes the values derived from the URDF and the semantic checks, which
``semantic`` times alone on the loaded description (``semantic_findings``).
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import pybullet

from robocram.robots import load_description
from robocram.robots.description_check import semantic_findings
from robocram.robots.interface_facts import description_facts


def _ms(start: float) -> float:
    return (time.perf_counter() - start) * 1000.0


def bench(name: str, repeats: int) -> None:
    """Print mean times [ms] of each step for robot ``name``."""
    totals = {"load+check": 0.0, "semantic": 0.0, "facts": 0.0, "to_urdf": 0.0, "pybullet": 0.0}
    client = pybullet.connect(pybullet.DIRECT)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / f"{name}.urdf"
        for _ in range(repeats):
            start = time.perf_counter()
            desc = load_description(name)
            totals["load+check"] += _ms(start)
            start = time.perf_counter()
            semantic_findings(desc)
            totals["semantic"] += _ms(start)
            start = time.perf_counter()
            facts = description_facts(desc)
            totals["facts"] += _ms(start)
            assert desc.model is not None
            start = time.perf_counter()
            desc.model.to_urdf(path)
            totals["to_urdf"] += _ms(start)
            start = time.perf_counter()
            pybullet.loadURDF(str(path), physicsClientId=client)
            totals["pybullet"] += _ms(start)
    pybullet.disconnect(client)
    assert desc.model is not None
    figures = "  ".join(f"{k} {v / repeats:7.2f} ms" for k, v in totals.items())
    print(f"{name:10s} joints {len(desc.model.joints):3d} facts {len(facts):4d}  {figures}")


if __name__ == "__main__":
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 10
    for robot in ("pr2", "hsrb", "boxy", "quadrotor"):
        bench(robot, count)
