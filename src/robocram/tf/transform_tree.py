"""A tree of named frames, each placed in its parent, answering "where is A in B".

Like tf2's buffer without the history: every frame keeps only its latest transform,
because the projection world is a snapshot. Lookups compose the two parent chains up to
the common root, so they cost a few pose products. The world feeds the tree through the
:class:`TransformSource` protocol (every frame's pose in a fixed frame such as ``map``),
so this layer never imports the world.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Protocol, overload, runtime_checkable

from robocram.tf.errors import TfUsageError, TransformError, unknown_frame
from robocram.tf.pose import Pose, PoseLike
from robocram.tf.stamped import PoseStamped, TransformStamped


@runtime_checkable
class TransformSource(Protocol):
    """Anything that knows where its frames are, e.g. the PyBullet world."""

    def frame_poses(self) -> Mapping[str, Pose]:
        """Return every frame's pose in the fixed frame (``map`` unless told otherwise)."""
        ...


class TransformTree:
    """Frames linked child -> parent by the child's pose in the parent.

    >>> tree = TransformTree()
    >>> tree.set_transform("map", "base_footprint", Pose((1, 0, 0)))
    >>> tree.set_transform("base_footprint", "head", Pose((0, 0, 1)))
    >>> tree.lookup("map", "head").position
    (1.0, 0.0, 1.0)
    """

    def __init__(self) -> None:
        self._parent: dict[str, str] = {}
        self._pose_in_parent: dict[str, Pose] = {}
        self._stamp: dict[str, float] = {}
        self._fed: set[str] = set()

    @classmethod
    def from_source(cls, source: TransformSource, fixed_frame: str = "map") -> TransformTree:
        """A new tree holding every frame of ``source`` as a child of ``fixed_frame``."""
        tree = cls()
        tree.update_from(source, fixed_frame)
        return tree

    @overload
    def set_transform(self, transform: TransformStamped, /) -> None: ...

    @overload
    def set_transform(
        self, parent: str, child: str, pose_in_parent: PoseLike, /, stamp: float = 0.0
    ) -> None: ...

    def set_transform(
        self,
        transform: TransformStamped | str,
        child: str | None = None,
        pose_in_parent: PoseLike | None = None,
        /,
        stamp: float = 0.0,
    ) -> None:
        """Place ``child`` in ``parent``; a TransformStamped or ``(parent, child, pose)``.

        Re-parenting a frame is allowed; closing a cycle raises :class:`TransformError`.
        """
        if isinstance(transform, TransformStamped):
            t = transform
        elif child is None or pose_in_parent is None:
            raise TfUsageError("set_transform takes a TransformStamped or (parent, child, pose)")
        else:
            t = TransformStamped.from_pose(transform, child, pose_in_parent, stamp)
        self._check_no_cycle(t.frame_id, t.child_frame_id)
        self._parent[t.child_frame_id] = t.frame_id
        self._pose_in_parent[t.child_frame_id] = t.pose
        self._stamp[t.child_frame_id] = t.stamp

    def update_from(self, source: TransformSource, fixed_frame: str = "map") -> None:
        """Replace the frames fed by earlier updates with the poses ``source`` gives now.

        Frames the source no longer names (removed objects) are dropped; frames set by
        hand with :meth:`set_transform` are kept.
        """
        poses = source.frame_poses()
        for frame in self._fed - set(poses):
            if self._parent.get(frame) == fixed_frame:
                self._drop(frame)
        self._fed = set()
        for frame, pose in poses.items():
            if frame == fixed_frame:
                continue
            self.set_transform(fixed_frame, frame, pose)
            self._fed.add(frame)

    def _drop(self, frame: str) -> None:
        del self._parent[frame]
        del self._pose_in_parent[frame]
        del self._stamp[frame]

    def _check_no_cycle(self, parent: str, child: str) -> None:
        frame: str | None = parent
        while frame is not None:
            if frame == child:
                raise TransformError(
                    f"placing {child!r} under {parent!r} would close a cycle: {parent!r} "
                    f"already hangs below {child!r}; remove or re-parent one of them first",
                    child,
                    self.frames(),
                )
            frame = self._parent.get(frame)

    def frames(self) -> tuple[str, ...]:
        """Every frame name the tree knows, sorted."""
        return tuple(sorted(set(self._parent) | set(self._parent.values())))

    def __contains__(self, frame: object) -> bool:
        return frame in self._parent or frame in self._parent.values()

    def parent(self, frame: str) -> str | None:
        """The parent of ``frame``, or None for a root frame."""
        self._require(frame)
        return self._parent.get(frame)

    def stamp(self, frame: str) -> float:
        """Time stamp [s] of the transform placing ``frame`` in its parent (0 for a root)."""
        self._require(frame)
        return self._stamp.get(frame, 0.0)

    def _require(self, frame: str) -> None:
        if frame not in self:
            raise unknown_frame(frame, self.frames())

    def _pose_in_root(self, frame: str) -> tuple[str, Pose]:
        pose = Pose()
        while frame in self._parent:
            pose = self._pose_in_parent[frame] * pose
            frame = self._parent[frame]
        return frame, pose

    def lookup(self, target_frame: str, source_frame: str) -> Pose:
        """Pose of ``source_frame`` expressed in ``target_frame`` (``target_T_source``)."""
        self._require(target_frame)
        self._require(source_frame)
        root_t, pose_t = self._pose_in_root(target_frame)
        root_s, pose_s = self._pose_in_root(source_frame)
        if root_t != root_s:
            raise TransformError(
                f"frames {target_frame!r} (tree rooted at {root_t!r}) and {source_frame!r} "
                f"(rooted at {root_s!r}) are not connected; add a transform linking the trees",
                source_frame,
                self.frames(),
            )
        return pose_t.inverse() * pose_s

    def can_transform(self, target_frame: str, source_frame: str) -> bool:
        """Whether both frames are known and connected."""
        if target_frame not in self or source_frame not in self:
            return False
        return self._pose_in_root(target_frame)[0] == self._pose_in_root(source_frame)[0]

    def transform_pose(self, pose: PoseStamped, target_frame: str) -> PoseStamped:
        """The same pose expressed in ``target_frame``; the stamp is kept."""
        if not isinstance(pose, PoseStamped):
            raise TfUsageError(
                f"transform_pose needs a PoseStamped (a pose with its frame), got {pose!r}"
            )
        if pose.frame_id == target_frame:
            self._require(target_frame)
            return pose
        target_t_source = self.lookup(target_frame, pose.frame_id)
        return pose.with_frame(target_frame, target_t_source * pose.pose)

    def transform(self, target_frame: str, source_frame: str) -> TransformStamped:
        """The transform ``target_T_source`` as a TransformStamped (stamp of the source)."""
        pose = self.lookup(target_frame, source_frame)
        return TransformStamped.from_pose(
            target_frame, source_frame, pose, self._stamp.get(source_frame, 0.0)
        )
