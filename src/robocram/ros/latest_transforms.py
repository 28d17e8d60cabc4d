"""The latest transform of each frame a node heard on ``/tf`` and ``/tf_static``.

A robot's tf is a tree (robot_state_publisher: links parent -> child, the base in
``odom`` or ``map``), published at 30 Hz or more: our ROS 2 node keeps only each frame's
latest transform as it arrives and composes a frame's pose in another when the plan side
asks, walking up only the chains of the frames asked for, never the whole tree.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from robocram.ros.tf_cdr import Transform
from robocram.tf import Pose, Quaternion, TransformTree, Vector3
from robocram.tf.errors import unknown_frame


class LatestTransforms:
    """``child: (parent, translation, rotation)``, the latest of each (not thread-safe:
    the node calls it holding its state lock)."""

    def __init__(self) -> None:
        self._latest: dict[str, tuple[str, Vector3, Quaternion]] = {}

    def update(self, transforms: Iterable[Transform]) -> None:
        """Keep these transforms (tf2 frame names may carry a leading slash)."""
        self._latest.update(
            (child.lstrip("/"), (parent.lstrip("/"), translation, rotation))
            for parent, child, translation, rotation in transforms
        )

    def frames(self) -> list[str]:
        """Every frame the transforms name, sorted."""
        return sorted(set(self._latest) | {parent for parent, _, _ in self._latest.values()})

    def lookups(self, target: str, sources: Sequence[str]) -> dict[str, Pose]:
        """The pose of each of ``sources`` in ``target``.

        Raises:
            TransformError: a frame no transform names, or two frames in trees apart.
        """
        named = set(self._latest) | {parent for parent, _, _ in self._latest.values()}
        for frame in (target, *sources):
            if frame not in named:
                raise unknown_frame(frame, sorted(named))
        tree = TransformTree()
        placed: set[str] = set()
        for frame in (target, *sources):
            while frame in self._latest and frame not in placed:
                parent, translation, rotation = self._latest[frame]
                tree.set_transform(parent, frame, Pose(translation, rotation))
                placed.add(frame)
                frame = parent
        return {source: tree.lookup(target, source) for source in sources}
