"""What a checker's levers take from the model alone is kept with the model; what the
robot holds is read per checker.

``LeverData.of`` is asked by every motion's checker; its rows, masks and chain lengths
follow from the model and the joints and links named, so they are worked out once per
model and tuples. Here they must be what a fresh working-out gives, and agree with the
model's tree walked independently (a link is below a joint exactly when
``links_below`` says so); another joint set gets its own; a held mug (not the model's)
is still seen by the next checker: its carrier and the wrist's larger radius.
"""

from __future__ import annotations

import numpy as np

from robocram.motion.bullet_scene import BulletScene
from robocram.motion.joint_levers import _worked_out, links_below
from robocram.scenes import tabletop_scene
from robocram.world import RobotHandle

RIGHT = (
    "torso_lift_joint", "r_shoulder_pan_joint", "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
    "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip
LEFT = tuple(j.replace("r_", "l_", 1) for j in RIGHT)

FIELDS = (
    "frame_links", "row", "centre_rows", "joint_rows", "local_axes", "prismatic", "below",
    "after", "chains",
)  # fmt: skip


def _same(a: object, b: object) -> bool:
    return all(
        np.array_equal(getattr(a, f), getattr(b, f)) if isinstance(getattr(a, f), np.ndarray)
        else getattr(a, f) == getattr(b, f)
        for f in FIELDS
    )  # fmt: skip


def test_kept_levers_are_a_fresh_working_out_and_the_trees() -> None:
    world = tabletop_scene("pr2").world
    robot = RobotHandle.of(world, "pr2")
    model = robot.description.model
    first = BulletScene(robot, RIGHT).lever_data()
    second = BulletScene(robot, RIGHT).lever_data()
    assert second.below is first.below and second.chains is first.chains  # kept
    moving = BulletScene(robot, RIGHT).moving_links
    assert _same(first, _worked_out(model, RIGHT, moving))
    for k, joint in enumerate(RIGHT):
        below = set(links_below(robot, [joint]))
        assert {link for link, row in first.row.items() if first.below[row, k]} == below
    left = BulletScene(robot, LEFT).lever_data()
    assert left.below is not first.below
    assert _same(left, _worked_out(model, LEFT, BulletScene(robot, LEFT).moving_links))
    world.close()


def test_a_held_mug_is_seen_by_the_next_checker() -> None:
    world = tabletop_scene("pr2").world
    robot = RobotHandle.of(world, "pr2")
    empty = BulletScene(robot, RIGHT).lever_data()
    world.attach("mug-1", "pr2", "r_wrist_roll_link")
    holding = BulletScene(robot, RIGHT).lever_data()
    assert holding.below is empty.below  # the model's part is the same
    assert empty.carriers == {} and holding.carriers == {"mug-1": "r_wrist_roll_link"}
    wrist = empty.row["r_wrist_roll_link"]
    assert holding.radii[wrist] > empty.radii[wrist]  # the mug rides on it
    world.close()
