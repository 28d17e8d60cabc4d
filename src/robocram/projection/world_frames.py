"""The world as a transform source, and a transform tree that always reads it fresh.

Inside ``simulated_robot`` plans call ``transform_pose`` as in CRAM; the tree bound there
is a :class:`LiveTransformTree` that re-reads the world before every lookup, so a pose
asked for after the robot moved is never stale. Frames are ``map``, every object by name
and every robot link by name (the first robot wins if two share a link name).
"""

from __future__ import annotations

from collections.abc import Mapping

from robocram.tf import Pose, TransformSource, TransformTree
from robocram.world import World


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


class LiveTransformTree(TransformTree):
    """A transform tree refreshed from its source before every lookup."""

    def __init__(self, source: TransformSource, fixed_frame: str = "map") -> None:
        super().__init__()
        self.source = source
        self.fixed_frame = fixed_frame
        self.update_from(source, fixed_frame)

    def refresh(self) -> None:
        """Re-read every frame of the source."""
        self.update_from(self.source, self.fixed_frame)

    def lookup(self, target_frame: str, source_frame: str) -> Pose:
        """Pose of ``source_frame`` in ``target_frame``, as the world is now."""
        self.refresh()
        return super().lookup(target_frame, source_frame)

    def can_transform(self, target_frame: str, source_frame: str) -> bool:
        """Whether both frames exist now and are connected."""
        self.refresh()
        return super().can_transform(target_frame, source_frame)

    def frames(self) -> tuple[str, ...]:
        """Every frame name the world has now, sorted."""
        self.refresh()
        return super().frames()
