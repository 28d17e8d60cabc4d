"""The parts the plans need: at least one arm, a gripper on each, and a camera.

A description without them loads and drives what it has, and every name checks out, yet
pick-up plans then fail far from the cause ("no arm of [] picked up ..."). So their
absence fails the card, naming what to add and, for a camera, the link it likely is.
"""

from __future__ import annotations

from robocram.robot_check.report_card import CheckResult
from robocram.robots import LoadedDescription
from robocram.robots.draft.cameras import likely_camera_link
from robocram.robots.draft.model_tree import ModelTree


def part_presence(desc: LoadedDescription) -> list[CheckResult]:
    """One result per missing part: no arm, an arm without gripper, no camera."""
    arms = {key: arm for key, arm in desc.arms.items() if key != desc.neck_arm}
    results: list[CheckResult] = []
    if not arms:
        results.append(
            CheckResult(
                "arms",
                False,
                "no arm is described: the plans have nothing to grasp with",
                "add an ArmDescription per arm (end_effector_link: its wrist; gripper_joints: "
                "its finger joints); the draft finds arms that end in fingers",
            )
        )
    for key, arm in arms.items():
        if not arm.gripper_joints and arm.gripper is None:
            results.append(
                CheckResult(
                    f"{key} arm: gripper",
                    False,
                    f"arm {key!r} has no gripper joints: it cannot hold anything",
                    "give its finger joints as gripper_joints (or a GripperDescription)",
                )
            )
    if not desc.cameras:
        hands = [arm.end_effector_link for arm in arms.values()]
        likely = likely_camera_link(ModelTree(desc.model), hands)
        results.append(
            CheckResult(
                "camera",
                False,
                "no camera is described: the plans look and detect before they grasp",
                f"draft again with `robocram robot draft URDF --camera LINK` (likely "
                f"{likely!r}), or add a CameraDescription on an optical frame",
            )
        )
    return results
