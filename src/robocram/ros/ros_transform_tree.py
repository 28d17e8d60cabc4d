"""The transform tree of a robot behind ROS: lookups go to tf2, fed from ``/tf``.

Plans call ``transform_pose`` as in projection; inside ``ros_robot`` the bound tree asks
our ROS node's tf2 buffer for the latest transform. Frames set by hand with
``set_transform`` stay local and are answered locally.
"""

from __future__ import annotations

from collections.abc import Callable

from robocram.ros.errors import RosNodeError
from robocram.ros.transport import Transport
from robocram.tf import Pose, TransformError, TransformTree
from robocram.tf.errors import unknown_frame


class RosTransformTree(TransformTree):
    """A :class:`~robocram.tf.TransformTree` answered by tf2 through a transport."""

    def __init__(self, transport: Callable[[], Transport]) -> None:
        super().__init__()
        self._transport = transport

    def _remote_frames(self) -> tuple[str, ...]:
        return self._transport().frames()

    def frames(self) -> tuple[str, ...]:
        """Every frame tf2 knows and every local one, sorted."""
        return tuple(sorted(set(self._remote_frames()) | set(super().frames())))

    def __contains__(self, frame: object) -> bool:
        return super().__contains__(frame) or frame in self._remote_frames()

    def lookup(self, target_frame: str, source_frame: str) -> Pose:
        """The latest pose of ``source_frame`` in ``target_frame``."""
        if super().can_transform(target_frame, source_frame):
            return super().lookup(target_frame, source_frame)
        try:
            return self._transport().lookup_transform(target_frame, source_frame)
        except RosNodeError as err:
            known = self.frames()
            for frame in (target_frame, source_frame):
                if frame not in known:
                    raise unknown_frame(frame, known) from err
            raise TransformError(
                f"tf2 cannot transform {source_frame!r} into {target_frame!r}: {err}",
                source_frame,
                known,
            ) from err

    def can_transform(self, target_frame: str, source_frame: str) -> bool:
        """Whether both frames are known and connected now."""
        try:
            self.lookup(target_frame, source_frame)
        except TransformError:
            return False
        return True
