"""The one small interface between the ROS process modules and a ROS implementation.

Process modules speak plain dictionaries in the layout of the ROS messages (as rosbridge
does: times ``{"secs", "nsecs"}``) and never import rospy or rclpy. :class:`Ros1Transport`
implements this with rospy and actionlib in a child process, :class:`Ros2Transport` with
rclpy (docs/ros.md, docs/ros2.md); both through ``node_process.py``.
"""

from __future__ import annotations

import threading
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from enum import Enum
from typing import Any, Protocol

from robocram.tf import Pose

RosDict = dict[str, Any]
# joint-state and base-transform messages arrived so far, and the robot's stamp [s] of the
# result the mark is taken at (0.0: unknown; ROS 2 results carry none)
StateMark = tuple[int, int, float]


class GoalState(Enum):
    """Terminal states of an action goal (actionlib's GoalStatus numbers) and LOST."""

    PREEMPTED = 2
    SUCCEEDED = 3
    ABORTED = 4
    REJECTED = 5
    RECALLED = 8
    LOST = 100


@dataclass(frozen=True)
class GoalOutcome:
    """How a goal ended: its state, the server's status text, the result, the state
    messages that had arrived when it did (state arriving after ``mark``, or stamped at or
    just after its result's stamp, shows its end)
    and the last feedback the server sent (e.g. Nav2's distance remaining; may be empty)."""

    state: GoalState
    status_text: str
    result: RosDict
    mark: StateMark = (0, 0, 0.0)
    arrived: float = 0.0  # [s] time.monotonic() when our node got the result (benchmarks)
    feedback: RosDict = field(default_factory=dict)


@dataclass
class GoalHandle:
    """A goal sent to ``server``; ``outcome`` is set (and ``done`` notified) when it ends."""

    goal_id: int
    server: str
    sent: float = 0.0  # [s] time.monotonic() when our node handed the goal to ROS
    done: threading.Condition = field(default_factory=threading.Condition)
    outcome: GoalOutcome | None = None

    def finish(self, outcome: GoalOutcome) -> None:
        """Record the outcome once (later ones are ignored) and wake the waiters."""
        with self.done:
            if self.outcome is None:
                self.outcome = outcome
            self.done.notify_all()


@dataclass(frozen=True)
class StateSnapshot:
    """The robot's state as ROS reports it at one moment (:meth:`Transport.snapshot`)."""

    joints: dict[str, float]
    environment: dict[str, dict[str, float]]  # by topic
    base: Pose  # the base frame in the target frame
    objects: dict[str, Pose]  # the objects tf knows, in the target frame


class Transport(Protocol):
    """What the process modules need from ROS: actions, joint states and transforms."""

    def send_goal(self, server: str, goal: RosDict) -> GoalHandle:
        """Send ``goal`` to the action ``server``; raises RosConnectionLost if none answers."""
        ...

    def cancel_goal(self, handle: GoalHandle) -> None:
        """Ask the server to cancel the goal (its outcome arrives as PREEMPTED or RECALLED)."""
        ...

    def wait_for_state(
        self,
        after: StateMark | None,
        timeout: float,
        ends_at: Mapping[str, float] | None = None,
    ) -> bool:
        """Wait until joint states and the base's transform arrived after ``after`` (an
        outcome's mark; None: from now on), or a state stamped at or just after the result
        (the robot's stamps compared with each other, never with our clock).
        ``ends_at``: the joints a finished trajectory ends at; a state held already that
        shows them, every transform stamped no earlier, is the state after it."""
        ...

    def settle(
        self,
        after: StateMark,
        timeout: float,
        ends_at: Mapping[str, float] | None,
        snapshot: tuple[str, str, Sequence[str]],
    ) -> StateSnapshot | None:
        """:meth:`wait_for_state`, then :meth:`snapshot` of ``(target_frame, base_frame,
        objects)``, in one request; None if no state came within ``timeout``."""
        ...

    def joint_states(self) -> dict[str, float]:
        """The latest joint positions [rad | m] by joint name."""
        ...

    def environment_joint_states(self) -> dict[str, dict[str, float]]:
        """The latest joint positions of the environment (drawers, doors) by topic."""
        ...

    def lookup_transform(self, target_frame: str, source_frame: str) -> Pose:
        """The latest pose of ``source_frame`` in ``target_frame``."""
        ...

    def lookup_transforms(self, target_frame: str, source_frames: Sequence[str]) -> dict[str, Pose]:
        """The latest poses of ``source_frames`` in ``target_frame``, in one request (the
        world mirror reads the base and every object after each goal)."""
        ...

    def frames(self) -> tuple[str, ...]:
        """Every frame the transforms name, sorted."""
        ...

    def snapshot(self, target_frame: str, base_frame: str, objects: Sequence[str]) -> StateSnapshot:
        """What the world mirror reads after each goal, in one request: the joints, the
        environments' joints, the base's pose and the poses of the ``objects`` tf knows."""
        ...

    def close(self) -> None:
        """Cancel what runs, leave ROS and stop every thread and process of the transport."""
        ...
