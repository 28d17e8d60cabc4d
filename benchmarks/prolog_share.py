"""The Prolog share of a cold PR2 transport, sampled: what issue 40's cold transport spends
in robocram's Prolog engine, without timing each of its ~140 queries (a timer per call
costs more than many of them do).

A CPU timer (``ITIMER_PROF``, every 0.5 ms of process CPU) samples the Python stack. A
sample is ``prolog`` when the innermost robocram frame is in ``robocram/logic`` (the
engine, the compiler, generated clause code; not ``lru.py``, the store motion/ and
world/ use too), ``host`` when a logic frame is further out (the Python predicates
Prolog calls: designator properties, world state), else ``rest``. The milliseconds are
each share times the mean CPU of the timed transports. Each run builds a fresh kitchen
and times one transport, as ``cold_transport`` does (``--second``: the second transport
in that scene instead). The process's first transport is not sampled. Compare trees
back to back (``PYTHONPATH=<tree>/src``): the shares move less with the load than the
milliseconds. Usage: python benchmarks/prolog_share.py [RUNS] [--second]
"""

from __future__ import annotations

import statistics
import sys
from collections import Counter
from types import FrameType

from cold_transport import _timed_transport
from sampled_transports import sampled_transports
from transport_timing import _mug_spot

from robocram.scenes import KitchenScene


class Sampler:
    """Counts the samples of each kind while on (:meth:`start` to :meth:`stop`)."""

    def __init__(self) -> None:
        self.on = False
        self.kinds: Counter[str] = Counter()
        self.places: Counter[str] = Counter()  # innermost logic function of prolog samples

    def start(self) -> None:
        self.on = True

    def stop(self) -> None:
        self.on = False

    def sample(self, signum: int, frame: FrameType | None) -> None:
        if not self.on:
            return
        inner = None
        while frame is not None:
            kind = _kind(frame)
            if kind == "logic" and inner is None:
                code = frame.f_code
                self.places[f"{code.co_filename.rsplit('/', 1)[-1]}:{code.co_name}"] += 1
                self.kinds["prolog"] += 1
                return
            if kind == "logic":
                self.kinds["host"] += 1
                return
            inner = inner or kind
            frame = frame.f_back
        self.kinds["rest"] += 1


def _kind(frame: FrameType) -> str | None:
    """'logic' or 'other' for a robocram frame, None for any other."""
    name = frame.f_code.co_filename
    if name == "<robocram clause>":
        return "logic"
    at = name.find("/robocram/")
    if at < 0 or name.endswith("/logic/lru.py"):
        return None
    return "logic" if name.startswith("logic/", at + len("/robocram/")) else "other"


def _second_transport(scene: KitchenScene, run: int) -> None:
    """The transport before the sampled one in the same scene (``--second``)."""
    _timed_transport(scene, _mug_spot(run % 10))


def main(runs: int, second: bool) -> None:
    sampler = Sampler()
    before = _second_transport if second else None
    cpu = sampled_transports(sampler, runs, before)
    total = sum(sampler.kinds.values())
    mean = statistics.mean(cpu)
    shares = "  ".join(
        f"{k} {v / total * 100:.1f}% = {v / total * mean:.2f} ms"
        for k, v in sorted(sampler.kinds.items())
    )
    which = "second transport in a fresh scene" if second else "cold transport"
    print(f"pr2 {which}: CPU mean {mean:.1f} ms, median {statistics.median(cpu):.1f} ms")
    print(f"  {total} samples: {shares}")
    print(f"  most sampled in Prolog: {sampler.places.most_common(8)}")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    main(int(args[0]) if args else 20, "--second" in sys.argv)
