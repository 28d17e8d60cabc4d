"""The physics part of a world: stepping time, and how bodies come to rest on each other.

Reached as ``world.physics``. Stepping keeps what the world promises between steps:
robots hold their joints and attached objects follow their links.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from robocram.world import spatial_relations
from robocram.world.errors import WorldValueError
from robocram.world.settling import LOOK, at_rest
from robocram.world.sleeping import asleep
from robocram.world.world_object import WorldObject
from robocram.world.world_part import WorldPart
from robocram.world.world_tables import ObjectRef, check_time_step


class Physics(WorldPart):
    """Simulated time of one world: its client, steps, settling and resting relations."""

    def client(self) -> int:
        """The pybullet client id, for the world's own helper modules; closed: an error."""
        return self._tables.physics_client()

    @property
    def time(self) -> float:
        """Simulated time [s] so far (put back by a restored snapshot)."""
        return self._tables.time

    def step(self) -> None:
        """Advance physics one time step; robots hold their joints, attachments follow.

        Held joints of robots are put back after the step, so their motors are off.
        """
        self._tables.step()

    def simulate(self, seconds: float, stop_check: Callable[[], None] | None = None) -> int:
        """Run physics for ``seconds`` [s] of simulated time; return the number of steps.

        ``stop_check`` (e.g. a task's ``checkpoint``) is called before every step; it ends
        the simulation by raising, leaving the world after the last whole step.
        """
        steps = self._steps(seconds)
        for _ in range(steps):
            if stop_check is not None:
                stop_check()
            self._tables.step()
        return steps

    def settle(
        self, obj: ObjectRef, seconds: float, stop_check: Callable[[], None] | None = None
    ) -> int:
        """Run physics until ``obj`` rests or ``seconds`` [s] have passed; return the steps.

        ``obj`` is looked at every :data:`~robocram.world.settling.LOOK` and rests when it
        stayed still between two looks (:func:`~robocram.world.settling.at_rest`). The
        other bodies sleep meanwhile unless something moving touches them (a fifth of
        the cost of a kitchen step; see :mod:`~robocram.world.sleeping`); woken, they
        take one more step with ``obj``, which leaves them as awake as before. A stop
        (``stop_check`` raising) takes that step too, then passes on.
        """
        w = self._world
        handle = w.object(obj)
        steps = self._steps(seconds)
        if steps == 0:
            return 0
        look = max(1, round(LOOK / w.time_step))
        cid = self._tables.physics_client()
        others = [b for o in w.objects() if o is not handle for b in o.bodies]
        done = 0
        try:
            with asleep(others, cid):
                before = w.pose(handle)
                while done < steps:
                    for _ in range(min(look, steps - done)):
                        if stop_check is not None:
                            stop_check()
                        self._tables.step()
                        done += 1
                    now = w.pose(handle)
                    if at_rest(before, now):
                        break
                    before = now
        finally:
            self._tables.step()  # Bullet marks the woken bodies awake at the end of a step
        return done + 1

    def _steps(self, seconds: float) -> int:
        """Physics steps in ``seconds`` [s] of simulated time."""
        if not (seconds >= 0 and math.isfinite(seconds)):
            raise WorldValueError(f"simulate needs a finite duration >= 0 [s], got {seconds!r}")
        check_time_step(self._world.time_step)
        return round(seconds / self._world.time_step)

    def stable(self, obj: ObjectRef | Sequence[ObjectRef] | None = None) -> bool:
        """Whether ``obj`` (default: all free objects) stays within 5 mm / 0.15 rad."""
        w = self._world
        if obj is None:
            return spatial_relations.stable(w, self.simulate)
        refs = [obj] if isinstance(obj, str | WorldObject) else list(obj)
        return spatial_relations.stable(w, self.simulate, [w.object(o) for o in refs])

    def supported_by(self, obj: ObjectRef, support: ObjectRef) -> bool:
        """Whether ``obj`` touches ``support`` and is above it."""
        w = self._world
        return spatial_relations.supported_by(w, w.object(obj), w.object(support))

    def above(self, a: ObjectRef, b: ObjectRef) -> bool:
        """Whether ``a`` is over ``b`` (x-y overlap, a's centre above b's top)."""
        return spatial_relations.above(self._world, self._world.object(a), self._world.object(b))

    def below(self, a: ObjectRef, b: ObjectRef) -> bool:
        """Whether ``a`` is under ``b``."""
        return spatial_relations.below(self._world, self._world.object(a), self._world.object(b))
