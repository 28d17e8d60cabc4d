"""A new user's first result: fresh processes timed from outside, as ``python my_plan.py``.

Issue 40's first three rows, each the median of N fresh processes (wall time seen by this
process, CPU time of the child: user + system, from its rusage):

- ``import``: ``python -c "import robocram.plans, robocram.projection, robocram.scenes"``;
- ``script``: import, the PR2 kitchen (``kitchen_scene("pr2")``) and one mug transport to
  the table (``transport("mug", a.location(on=("kitchen", "table_top"), for_="mug-1"))``
  inside ``simulated_robot``, as ``cold_transport`` and the trajectory identity check do);
  the child's own split (import, scene, transport) is printed beside it;
- ``first``: in one process, the first transport (after its scene is built) against a
  later cold one (a fresh scene, the same process, the same mug), wall and CPU of each
  transport, scene build excluded.

Each child is this file run with ``--child KIND``; it imports robocram only there, so the
figures include the interpreter's start as the user pays it. Rows alternate per round so
load from other processes biases none. The CPU load average is printed: compare old and
new trees back to back (``PYTHONPATH=<tree>/src``), not against the goals' idle figures.
As an installed package runs: children write and use bytecode (``PYTHONDONTWRITEBYTECODE``
is dropped for them) and one untimed child per row runs first, writing the bytecode and
robocram's disk cache. ``--empty-cache`` gives every child a new cache folder instead
(``ROBOCRAM_CACHE_DIR``): a user's very first run on a machine, reachability maps included.
``--against OLD/src`` times another checkout in the same rounds, alternating, and prints
the ratios. Usage: python benchmarks/first_result_bench.py [N] [--empty-cache]
[--only KIND] [--against SRC]   (N fresh processes per row, default 10)
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

GOALS = {
    "import": "goal <= 0.4 s wall (issue 40: 1.1-1.5 s)",
    "script": "goal <= 1.0 s wall (issue 40: 2.7-3.1 s at load 4)",
    "first": "goal: first <= 1.5x a later cold one; cold <= 100 ms (issue 40: 0.56-1.14 s "
    "against 115-171 ms)",
}
KINDS = tuple(GOALS)


def _transport(robot: str) -> tuple[float, float, float, float]:
    """Build the kitchen and transport the mug once: scene and transport wall, CPU [s]."""
    from robocram.designators import a
    from robocram.plans.transport import transport
    from robocram.projection import simulated_robot
    from robocram.scenes import kitchen_scene

    wall, cpu = time.perf_counter(), time.process_time()
    scene = kitchen_scene(robot)
    built = time.perf_counter() - wall, time.process_time() - cpu
    wall, cpu = time.perf_counter(), time.process_time()
    with simulated_robot(scene.world, scene.robot):
        transport("mug", a.location(on=("kitchen", "table_top"), for_="mug-1"))
    moved = time.perf_counter() - wall, time.process_time() - cpu
    scene.world.close()
    return (*built, *moved)


def child(kind: str) -> dict[str, float]:
    """Run one kind's work in this (fresh) process; its own timings [s]."""
    wall, cpu = time.perf_counter(), time.process_time()
    import robocram.plans
    import robocram.projection
    import robocram.scenes  # noqa: F401  (the three a script imports)

    out = {"import": time.perf_counter() - wall, "import_cpu": time.process_time() - cpu}
    if kind == "import":
        return out
    scene, scene_cpu, moved, moved_cpu = _transport("pr2")
    out.update(scene=scene, scene_cpu=scene_cpu, transport=moved, transport_cpu=moved_cpu)
    if kind == "first":
        *_, cold, cold_cpu = _transport("pr2")
        out.update(cold=cold, cold_cpu=cold_cpu)
    return out


def run_child(kind: str, empty_cache: bool = False, src: str | None = None) -> dict[str, float]:
    """One fresh process of ``kind`` (importing robocram from ``src``, else as this one
    does): its wall and CPU seen from here, and its own split."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if src is not None:
        env["PYTHONPATH"] = src
    with tempfile.TemporaryDirectory() as folder:
        if empty_cache:
            env["ROBOCRAM_CACHE_DIR"] = folder
        return _timed_child(kind, env)


def _timed_child(kind: str, env: dict[str, str]) -> dict[str, float]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(
        [sys.executable, __file__, "--child", kind],
        capture_output=True, text=True, check=False, env=env,
    )  # fmt: skip
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        sys.exit(f"the {kind} child failed:\n{done.stderr}")
    figures: dict[str, float] = json.loads(done.stdout.strip().splitlines()[-1])
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    figures.update(process=wall, process_cpu=cpu)
    return figures


def _median(runs: list[dict[str, float]], key: str) -> float:
    return statistics.median(r[key] for r in runs)


def report(kind: str, runs: list[dict[str, float]], label: str = "") -> None:
    """The medians of ``kind``'s runs beside its goal."""
    m = {key: _median(runs, key) for key in runs[0]}
    if label:
        print(f"  {label}:")
    if kind == "import":
        line = f"import   process wall {m['process']:5.2f} s  CPU {m['process_cpu']:5.2f} s"
        line += f"   (the imports alone {m['import']:5.2f} s)"
    elif kind == "script":
        line = (
            f"script   process wall {m['process']:5.2f} s  CPU {m['process_cpu']:5.2f} s   "
            f"(import {m['import']:4.2f}, scene {m['scene']:4.2f}, transport "
            f"{m['transport']:4.2f} s wall)"
        )
    else:
        ratio = statistics.median(r["transport"] / r["cold"] for r in runs)
        line = (
            f"first    transport wall {1e3 * m['transport']:6.0f} ms  CPU "
            f"{1e3 * m['transport_cpu']:6.0f} ms;  later cold one wall {1e3 * m['cold']:5.0f} "
            f"ms  CPU {1e3 * m['cold_cpu']:5.0f} ms;  first/cold {ratio:4.2f}x"
        )
    print(f"{line}   [{GOALS[kind]}]", flush=True)


def _ratios(kind: str, this: list[dict[str, float]], other: list[dict[str, float]]) -> None:
    """This tree's medians over the other's, wall and CPU."""
    key = "transport" if kind == "first" else "process"
    wall = _median(this, key) / _median(other, key)
    cpu = _median(this, f"{key}_cpu") / _median(other, f"{key}_cpu")
    print(f"  {kind}: this tree / the other: wall {wall:4.2f}x  CPU {cpu:4.2f}x", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", type=int, nargs="?", default=10, help="fresh processes per row")
    parser.add_argument("--child", choices=KINDS, help=argparse.SUPPRESS)
    parser.add_argument("--only", choices=KINDS, action="append", help="rows to run")
    parser.add_argument("--empty-cache", action="store_true", help="a new cache per child")
    parser.add_argument(
        "--against", metavar="SRC", help="another tree's src folder, timed in the same rounds"
    )
    args = parser.parse_args()
    if args.child:
        print(json.dumps(child(args.child)))
        return
    kinds = tuple(args.only or KINDS)
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    cache = "an empty robocram cache each" if args.empty_cache else "robocram's cache warm"
    print(f"first result: median of {args.runs} fresh processes ({cache}), load average {load}")
    trees: tuple[str | None, ...] = (None, args.against) if args.against else (None,)
    for kind in kinds:  # untimed: writes the bytecode (and the cache) as an install would
        for src in trees:
            run_child(kind, args.empty_cache, src)
    runs: dict[tuple[str, str | None], list[dict[str, float]]] = {}
    for r in range(args.runs):
        for kind in kinds if r % 2 == 0 else kinds[::-1]:
            for src in trees if r % 2 == 0 else trees[::-1]:
                runs.setdefault((kind, src), []).append(run_child(kind, args.empty_cache, src))
    for kind in kinds:
        for src in trees:
            label = "" if not args.against else f"robocram from {src or 'PYTHONPATH'}"
            report(kind, runs[(kind, src)], label)
        if args.against:
            _ratios(kind, runs[(kind, None)], runs[(kind, args.against)])
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"load average at the end {load}")


if __name__ == "__main__":
    main()
