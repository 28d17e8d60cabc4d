"""The world as a transform source, and a transform tree that always reads it fresh.

Inside ``simulated_robot`` plans call ``transform_pose`` as in CRAM; the tree bound there
is a :class:`LiveTransformTree` that re-reads the world before every lookup, so a pose
asked for after the robot moved is never stale. Frames are ``map``, every object by name
and every robot link by name (the first robot wins if two share a link name).
A source that can give one frame's pose (:class:`FramePoseSource`, the world) is read only
for the frames a lookup needs: re-reading a PR2's 86 links for each lookup cost more than
some motions.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Protocol, runtime_checkable

from robocram.tf import Pose, TransformError, TransformSource, TransformTree
from robocram.world import World


@runtime_checkable
class FramePoseSource(Protocol):
    """A transform source that can also say where one frame is (None: no such frame)."""

    def frame_poses(self) -> Mapping[str, Pose]: ...

    def frame_pose(self, frame: str) -> Pose | None: ...


class WorldFrames:
    """A :class:`~robocram.tf.TransformSource` over a world: objects and robot links in map."""

    def __init__(self, world: World) -> None:
        self.world = world

    def frame_poses(self) -> Mapping[str, Pose]:
        """Every object's and robot link's pose in ``map``, now."""
        world = self.world
        poses: dict[str, Pose] = {}
        for robot in world.robots():
            for link in world.link_names(robot):
                poses.setdefault(link, world.link_pose(robot, link))
        for obj in world.objects():
            poses.setdefault(obj.name, world.pose(obj))
        return poses

    def frame_pose(self, frame: str) -> Pose | None:
        """The pose of one frame in ``map`` now, found as :meth:`frame_poses` would."""
        world = self.world
        for robot in world.robots():
            if frame in robot.link_index:
                return world.link_pose(robot, frame)
        return world.pose(frame) if frame in world else None


class LiveTransformTree(TransformTree):
    """A transform tree refreshed from its source before every lookup.

    Over a :class:`FramePoseSource` it starts empty and reads a frame when a lookup or a
    membership test first names it: reading a PR2 world's ~90 frames at the start of
    every ``simulated_robot`` block cost more than the block's few lookups.
    """

    def __init__(self, source: TransformSource, fixed_frame: str = "map") -> None:
        super().__init__()
        self.source = source
        self.fixed_frame = fixed_frame
        self._frame_source: FramePoseSource | None = None
        self._checked: TransformSource | None = None  # the source _frame_source is for
        if self._one_frame_source() is None:
            self.update_from(source, fixed_frame)

    def _one_frame_source(self) -> FramePoseSource | None:
        """The source, when it can give one frame (the protocol check is slow: once)."""
        source = self.source
        if source is not self._checked:
            self._checked = source
            self._frame_source = source if isinstance(source, FramePoseSource) else None
        return self._frame_source

    def __contains__(self, frame: object) -> bool:
        if TransformTree.__contains__(self, frame):
            return True
        source = self._one_frame_source()
        if source is None or not isinstance(frame, str):
            return False
        if frame == self.fixed_frame:
            return True  # the root every frame of the source hangs below
        self._refresh_chain(source, frame)
        return TransformTree.__contains__(self, frame)

    def refresh(self) -> None:
        """Re-read every frame of the source."""
        self.update_from(self.source, self.fixed_frame)

    def lookup(self, target_frame: str, source_frame: str) -> Pose:
        """Pose of ``source_frame`` in ``target_frame``, as the world is now."""
        if not self._refresh_frames(target_frame, source_frame):
            return super().lookup(target_frame, source_frame)
        try:
            return super().lookup(target_frame, source_frame)
        except TransformError:  # the error lists every frame: give it the world's
            self.refresh()
            return super().lookup(target_frame, source_frame)

    def can_transform(self, target_frame: str, source_frame: str) -> bool:
        """Whether both frames exist now and are connected."""
        self._refresh_frames(target_frame, source_frame)
        return super().can_transform(target_frame, source_frame)

    def _refresh_frames(self, *frames: str) -> bool:
        """Re-read the source's frames that ``frames`` hang below (all of them when the
        source cannot give one frame); True when only those were read."""
        source = self._one_frame_source()
        if source is None:
            self.refresh()
            return False
        for frame in frames:
            self._refresh_chain(source, frame)
        return True

    def _refresh_chain(self, source: FramePoseSource, frame: str) -> None:
        """Walk up from ``frame`` past frames set by hand to the first one the source
        feeds (they hang right below the fixed frame) and re-read it."""
        seen: set[str] = set()
        current: str | None = frame
        while current is not None and current != self.fixed_frame and current not in seen:
            seen.add(current)
            if current in self._fed or not TransformTree.__contains__(self, current):
                pose = source.frame_pose(current)
                if pose is not None:
                    self.set_transform(self.fixed_frame, current, pose)
                    self._fed.add(current)
                elif current in self._fed and self.parent(current) == self.fixed_frame:
                    self._drop(current)
                    self._fed.discard(current)
                return
            current = self.parent(current)

    def frames(self) -> tuple[str, ...]:
        """Every frame name the world has now, sorted."""
        self.refresh()
        return super().frames()
