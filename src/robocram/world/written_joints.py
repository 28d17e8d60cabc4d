"""Which bodies' joints stand exactly as the world's tables last wrote them.

Every PyBullet joint write costs a broadphase update of each of the body's links, and a
check put back where it stands, an IK query's put-back or a trajectory's first sample
asks for the values the joints already have. The tables hold what they last wrote per
joint (:meth:`~robocram.world.world_tables.WorldTables.held_joints`); while the body's
joint counter (``Versions.joints``) is the one of their own last write, nothing else
(physics, a restored state) has moved the joints since, so a write of the held values
sets nothing new, velocities included (a write leaves them 0), and PyBullet is spared it.
The write still counts as one: the counters move and the holds and what the body carries
are updated as always.
"""

from __future__ import annotations

from collections.abc import Mapping

from robocram.world.versions import Versions


class WrittenJoints:
    """Per body: its joint counter right after the tables last wrote its joints."""

    def __init__(self) -> None:
        self._after: dict[str, int] = {}

    def already(
        self,
        name: str,
        versions: Versions,
        held: Mapping[int, float] | None,
        values: Mapping[int, float],
    ) -> bool:
        """Whether body ``name``'s joints stand at ``values`` (by slot) already: nothing
        but the tables wrote them since their last write, which held them so."""
        after = self._after.get(name)
        if after is None or held is None or after != versions.joints(name):
            return False
        return all(held.get(slot) == value for slot, value in values.items())

    def wrote(self, name: str, versions: Versions) -> None:
        """The tables just wrote body ``name``'s joints (the holds say to what)."""
        self._after[name] = versions.joints(name)

    def forget(self, name: str) -> None:
        """The holds of body ``name`` changed without a write, or it left: nothing known."""
        self._after.pop(name, None)
