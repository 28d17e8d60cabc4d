"""The joint values a world checker knows the robot stands at, so it writes no others.

Every PyBullet joint write costs a broadphase update of each of the body's links. A
checker posed at a configuration it already stands at (a straight motion's start, checked
for the contacts it begins with, then put back) would write the same values twice. The
values are known only while the world's clock says nothing at all was written since they
were read or written (``world.versions.tick``), and only
where a write would set nothing new: a joint simulation holds at its value (a write of
another would also hold it), a mimic joint's master only while its followers stand where
it puts them. Such a write is left out.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from robocram.robots import RobotModel
from robocram.robots.mimic import mimic_followers
from robocram.world import World

KEPT_FOLLOWERS = 64  # masters' values whose followers' values are kept per model


class KnownJoints:
    """The robot's joints as last read or written by one checker, while nothing else wrote."""

    def __init__(self, world: World, robot: str, model: RobotModel) -> None:
        self.world = world
        self.robot = robot
        self.followers = model.derived(_Followers)
        self._tick: int | None = None  # the world's clock when they were read or written
        self._values: dict[str, float] = {}

    def read(self, now: Mapping[str, float]) -> None:
        """Know the values of ``now`` (the robot's joints just read, mimic joints too) that
        a write would not change."""
        held = self.world.snapshots.held_joints(self.robot)
        masters = self.followers.masters
        known = {j: v for j, v in now.items() if j not in masters and held.get(j) == v}
        given = {m: now[m] for m in masters if m in now}
        followers = self.followers.of(given) if given else {}
        if given and all(now.get(f) == self._clamped(f, v) for f, v in followers.items()):
            known.update((m, v) for m, v in given.items() if held.get(m) == v)
        self._values = known
        self._tick = self.world.versions.tick

    def write(self, values: Mapping[str, float]) -> None:
        """Set ``values`` as ``world.set_joint_states`` does, unless the robot stands so."""
        known = self._values
        fresh = self._tick is not None and self._tick == self.world.versions.tick
        if fresh and all(known.get(j) == v for j, v in values.items()):
            return
        self.world.set_joint_states(self.robot, values)
        if not fresh:  # something was written since: what else stands as known is not
            self._values = {}
        self._values.update(values)  # a write of these again (clamped alike) is the same
        self._tick = self.world.versions.tick

    def _clamped(self, joint: str, value: float) -> float | None:
        """``value`` within ``joint``'s limits, as a write puts a follower (None: the
        robot has no such movable joint)."""
        if joint not in self.world.object(self.robot).joint_index:
            return None
        return self.world.bodies.joint_limits(self.robot, joint).clamp(float(value))

    def forget(self) -> None:
        """Know nothing (the checker's block ended: others may write from now on)."""
        self._tick = None
        self._values = {}


@dataclass
class _Followers:
    """A model's mimic masters, and their followers' values per masters' values (kept
    with the model: a checker asks at every block, a gripper's masters seldom move)."""

    model: RobotModel
    masters: frozenset[str] = frozenset()
    _found: dict[tuple[tuple[str, float], ...], dict[str, float]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        joints = self.model.joints.values()
        self.masters = frozenset(j.mimic.joint for j in joints if j.mimic is not None)

    def of(self, masters: Mapping[str, float]) -> dict[str, float]:
        """The values ``masters``' followers get from them (unclamped: where a limit
        would clamp one, it does not match and the masters count as unknown)."""
        key = tuple(sorted(masters.items()))
        found = self._found.get(key)
        if found is None:
            if len(self._found) >= KEPT_FOLLOWERS:
                self._found.clear()
            values = mimic_followers(self.model, masters)
            found = self._found[key] = {j: v for j, v in values.items() if j not in masters}
        return found
