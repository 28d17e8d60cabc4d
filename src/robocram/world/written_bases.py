"""What the world's tables last wrote to each body's base, while it still stands so.

PyBullet keeps a base's orientation as a quaternion but answers a read through a
rotation matrix, so a read is a pose a last bit away from the one written, and writing
that read back moves the body by that bit (a read, written, read again, alternates
between two values). A snapshot that stored the read and wrote it back would leave the
world a bit off from where it was, and what runs after it (a stand, an IK seed) would
depend on whether a snapshot was taken before. While the body's pose counter
(``Versions.pose``) is the one of the tables' own last write, nothing else (physics) has
moved it since, so writing the same inputs again puts PyBullet back exactly.
"""

from __future__ import annotations

from collections.abc import Sequence

from robocram.world.versions import Versions

Vector = tuple[float, ...]
BaseInput = tuple[int, Vector, Vector]  # body id, position [m], orientation (xyzw)


class WrittenBases:
    """Per object: the bases its bodies were last written with, and its pose counter then."""

    def __init__(self) -> None:
        self._written: dict[str, tuple[int, tuple[BaseInput, ...]]] = {}

    def wrote(self, name: str, versions: Versions, bases: Sequence[BaseInput]) -> None:
        """The tables just wrote object ``name``'s bases with ``bases`` (its counter moved)."""
        self._written[name] = (versions.pose(name), tuple(bases))

    def inputs(self, name: str, versions: Versions) -> dict[int, tuple[Vector, Vector]]:
        """The inputs that put object ``name``'s bodies where they stand, by body id; empty
        when something else (physics) moved it since the tables last wrote it."""
        kept = self._written.get(name)
        if kept is None or kept[0] != versions.pose(name):
            return {}
        return {body: (position, orientation) for body, position, orientation in kept[1]}

    def forget(self, name: str) -> None:
        """Object ``name`` left the world: nothing known."""
        self._written.pop(name, None)
