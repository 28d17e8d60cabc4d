"""PR2 mug transports in fresh kitchens with a CPU-timer stack sampler on during each: the
loop ``prolog_share`` and ``transport_shares`` both sample.

A CPU timer (``ITIMER_PROF``, every :data:`INTERVAL` of process CPU) calls the sampler's
``sample``; the process's first transport (it builds what the process keeps) is not sampled.
"""

from __future__ import annotations

import signal
from collections.abc import Callable
from types import FrameType
from typing import Protocol

from cold_transport import _timed_transport
from transport_timing import _mug_spot

from robocram.scenes import KitchenScene, kitchen_scene

INTERVAL = 0.0005  # [s] of process CPU between samples


class StackSampler(Protocol):
    """Takes timer signals; counts only between ``start`` and ``stop``."""

    def sample(self, signum: int, frame: FrameType | None) -> None: ...
    def start(self) -> None: ...
    def stop(self) -> None: ...


def sampled_transports(
    sampler: StackSampler, runs: int, before: Callable[[KitchenScene, int], None] | None = None
) -> list[float]:
    """CPU [ms] of ``runs`` transports, each in a fresh kitchen, sampled; ``before(scene,
    i)`` runs unsampled in each scene first (``prolog_share --second``: run ``i``'s transport
    there)."""
    signal.signal(signal.SIGPROF, sampler.sample)
    signal.setitimer(signal.ITIMER_PROF, INTERVAL, INTERVAL)
    try:
        scene = kitchen_scene("pr2")
        _timed_transport(scene, _mug_spot(0))
        scene.world.close()
        cpu = []
        for run in range(runs):
            scene = kitchen_scene("pr2")
            if before is not None:
                before(scene, run)
            sampler.start()
            _, used, _ = _timed_transport(scene, _mug_spot(run % 10))
            sampler.stop()
            cpu.append(used)
            scene.world.close()
        return cpu
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0, 0)
