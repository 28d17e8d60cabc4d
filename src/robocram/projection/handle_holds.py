"""The frames a hand holds a part's handle in while the part moves: from the front, then
from above.

The hand takes a handle from the front first (the handle frame's x out of the front,
``motion.part_path.pull_frame``); when no grasp roll holds it so, the frame is turned down
(``motion.part_path.from_above``, :data:`~robocram.motion.part_path.PITCHES`) and the
rolls are tried again. The pitch that last held a handle goes first (a drawer opened from
above is closed so); a suction hand's frame lies on the face it touches.
"""

from __future__ import annotations

from robocram.motion.part_path import PITCHES, from_above, pull_frame
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.suction import on_the_face
from robocram.tf import Pose


def hold_frames(
    robot: ProjectedRobot, arm: str, part: str, joint: str, handle: str
) -> list[tuple[float, Pose]]:
    """The frames to hold ``handle`` in, each with its pitch down [rad]: from the front,
    then from above (:data:`~robocram.motion.part_path.PITCHES`); the pitch that last held
    it first. A suction hand's frame is on the face it touches."""
    pull = pull_frame(robot.world, part, joint, handle)
    known = robot.held_pitches.get((part, handle))
    pitches = list(dict.fromkeys([*(() if known is None else (known,)), 0.0, *PITCHES]))
    gripper = robot.arm(arm).gripper
    suction = gripper is not None and gripper.is_suction
    frames = [(p, from_above(pull, p) if p else pull) for p in pitches]
    return [(p, on_the_face(robot, part, handle, f) if suction else f) for p, f in frames]


def remember_pitch(robot: ProjectedRobot, part: str, handle: str, pitch: float) -> None:
    """Keep the pitch from above that held ``handle`` (a grasp from the front is the first
    tried anyway)."""
    if pitch:
        robot.held_pitches[(part, handle)] = pitch
    else:
        robot.held_pitches.pop((part, handle), None)
