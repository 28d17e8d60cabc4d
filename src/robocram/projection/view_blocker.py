"""Which part of a robot blocks its camera, and what moves it out of the view.

"Park the arms" is the fix only when an arm is not parked. A parked arm hanging before
the camera needs another parking pose; an arm carrying the camera needs a parking pose
that turns it to look past its own hand; a link of the body (a torso cover, the base)
needs the camera looking from elsewhere.
"""

from __future__ import annotations

from robocram.projection.projected_robot import ProjectedRobot

PARKED = 0.02  # [rad | m] every joint this near its parking value: the arm is parked


def blocking_fix(robot: ProjectedRobot, link: str) -> tuple[str, bool | None]:
    """The fix for ``link`` blocking ``robot``'s camera, and whether its arm is parked
    (None: the link is on no arm)."""
    desc = robot.description
    joints = robot.world.joint_states(robot.name)
    camera = desc.cameras[0].frame if desc.cameras else ""
    for key, arm in desc.arms.items():
        if link not in (*arm.links, *arm.hand_links, *arm.gripper_links):
            continue
        parked = all(abs(joints.get(j, v) - v) <= PARKED for j, v in arm.parking.items())
        on_arm = camera in (*arm.links, *arm.hand_links)
        if on_arm:
            return (
                f"the camera rides on arm {key!r}, whose own link {link!r} is in its view: "
                f"give the arm a parking pose (its `parking`) that points the camera past the "
                "hand, or look with another camera",
                parked,
            )
        if parked:
            return (
                f"arm {key!r} is parked and its link {link!r} still hangs before the camera: "
                f"give arm {key!r} a parking pose (its `parking`) clear of the camera's view",
                parked,
            )
        return (
            f"arm {key!r} is not parked: park the arms before looking "
            "(perform(an.action(type='parking-arms')))",
            parked,
        )
    return (
        f"{link!r} is part of the robot's body, not of an arm: raise the torso, look from "
        "another stand, or mount the camera (its `frame`) where the body is out of its view",
        None,
    )
