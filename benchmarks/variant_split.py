"""Where a kitchen batch variant's CPU time goes: each low-level call of the projected
robot's process modules, location sampling and settling, each timed exclusively (a
location resolution inside a motion counts once, as a location), and the rest (plans,
designators, Prolog, the worker's set-up).

The variants of examples/batch_kitchen.yaml run in this one process with the batch
worker's runner. The first six are not timed: they build what a process keeps (both
arms' IK start tables, the reachability maps), which a 1,000-variant batch pays once per
worker. Compare two versions back to back; the machine's speed drifts by 15 %.
Usage: python benchmarks/variant_split.py [variants]   (default 40)
"""

from __future__ import annotations

import importlib
import sys
import tempfile
import time
from collections import defaultdict
from collections.abc import Callable, Iterator
from pathlib import Path

import robocram.designators.location_resolver as location_resolver
import robocram.projection.process_modules as process_modules
from robocram.batch.batch_spec import load_spec
from robocram.batch.worker import VariantRunner, WorkerConfig

SPEC = Path(__file__).resolve().parents[1] / "examples" / "batch_kitchen.yaml"
WARM_UP = 6  # variants run before timing
CALLS = ("move_base", "move_torso", "move_head", "detect", "inspect", "move_gripper_joint",
         "move_tcp", "move_joints", "move_part")  # fmt: skip


class Split:
    """Exclusive CPU time and calls per label; nested timed calls are taken out."""

    def __init__(self) -> None:
        self.calls: defaultdict[str, int] = defaultdict(int)
        self.seconds: defaultdict[str, float] = defaultdict(float)
        self._inner: list[float] = []

    def timed(self, label: str, call: Callable[[], object]) -> object:
        start = time.process_time()
        self._inner.append(0.0)
        try:
            return call()
        finally:
            spent = time.process_time() - start
            self.calls[label] += 1
            self.seconds[label] += spent - self._inner.pop()
            if self._inner:
                self._inner[-1] += spent


def _instrument(split: Split) -> None:
    """Wrap the process modules' calls, the location resolver's answers and settling."""
    for kind in vars(process_modules).values():
        if not isinstance(kind, type) or kind.__module__ != process_modules.__name__:
            continue
        for name in CALLS:
            if name in vars(kind):
                setattr(kind, name, _wrapped(split, name, vars(kind)[name]))
    solutions = location_resolver.LocationResolver.solutions

    def timed_solutions(self: location_resolver.LocationResolver, d: object) -> Iterator[object]:
        answers = solutions(self, d)
        while True:
            answer = split.timed("locations", lambda: next(answers, StopIteration))
            if answer is StopIteration:
                return
            yield answer

    setattr(location_resolver.LocationResolver, "solutions", timed_solutions)  # noqa: B010
    place = importlib.import_module("robocram.plans.place_object")
    setattr(place, "_settled", _wrapped(split, "settle", getattr(place, "_settled")))  # noqa: B009, B010


def _wrapped(split: Split, label: str, call: Callable[..., object]) -> Callable[..., object]:
    def timed(*args: object, **kwargs: object) -> object:
        return split.timed(label, lambda: call(*args, **kwargs))

    return timed


def main(count: int = 40) -> None:
    split = Split()
    _instrument(split)
    with tempfile.TemporaryDirectory() as folder:
        text = SPEC.read_text().replace("variants: 4", f"variants: {count + WARM_UP}")
        path = Path(folder) / "spec.yaml"
        path.write_text(text)
        spec = load_spec(path)
    runner = VariantRunner(WorkerConfig(spec.plan, spec.scene, spec.robot))
    variants = list(spec.variants)
    for k in range(WARM_UP):
        runner.run(k, variants[k])
    split.calls.clear()
    split.seconds.clear()
    start, succeeded = time.process_time(), 0
    for k, variant in enumerate(variants[WARM_UP:], WARM_UP):
        succeeded += runner.run(k, variant).succeeded
    cpu = time.process_time() - start
    rest = cpu - sum(split.seconds.values())
    print(f"variant_split: {count} kitchen transports, {succeeded} succeeded, "
          f"CPU {cpu / count * 1e3:.0f} ms per variant; the rest (plans, designators, "
          f"Prolog, set-up) {rest / count * 1e3:.1f} ms")  # fmt: skip
    for label in sorted(split.seconds, key=lambda k: -split.seconds[k]):
        calls, seconds = split.calls[label], split.seconds[label]
        print(f"  {label:20s} {calls / count:5.1f} calls {seconds / count * 1e3:7.1f} ms "
              f"({seconds / calls * 1e3:6.2f} ms per call)")  # fmt: skip


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 40)
