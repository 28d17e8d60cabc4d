"""A box around a whole hand is a planner's margin, not the hand: grasps reach inside it.

Some URDFs wrap a hand in an invisible collision box (TIAGo's ``hand_safety_box``, 20 x
11.5 x 18 cm over the Hey5 and 7 cm out past its palm), so that a planner keeps the hand
clear of everything. A grasp has to bring the object between the fingers, which is
inside that box: every grasp met it. A link of the hand that is no finger, has no visual
and only boxes, and whose boxes hold most of the fingers (with the hand open) is such a
margin; it loses its collision shapes. Links with a visual are the hand's body and are
never changed.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from robocram.robots.description import ArmDescription
from robocram.robots.model_pose import link_pose
from robocram.robots.robot_model import RobotModel
from robocram.robots.stand_in_size import is_stand_in
from robocram.robots.urdf_elements import Link

HELD_SHARE = 0.5  # a box holding more than this share of the finger links' origins
INSIDE = 1e-6  # [m]


def without_hand_envelopes(model: RobotModel, arms: Mapping[str, ArmDescription]) -> RobotModel:
    """``model`` with each hand's enveloping boxes taken out; ``model`` itself if none."""
    key = tuple(sorted((arm.end_effector_link, tuple(arm.gripper_links)) for arm in arms.values()))
    kept = model.derived(_envelope_free)
    if key not in kept:
        kept[key] = _stripped(model, arms)
    return kept[key]


def _envelope_free(model: RobotModel) -> dict[tuple[tuple[str, tuple[str, ...]], ...], RobotModel]:
    """The models stripped from ``model``, by the hands they were stripped for."""
    return {}


def _stripped(model: RobotModel, arms: Mapping[str, ArmDescription]) -> RobotModel:
    links = dict(model.links)
    for arm in arms.values():
        gripper = arm.gripper
        fingers = tuple(arm.gripper_links)
        if gripper is None or len(fingers) < 2:
            continue
        opened = gripper.at(1.0)
        origins = np.asarray([link_pose(model, f, opened).position for f in fingers])
        for name in arm.hand_links:
            link = links[name]
            if name in fingers or not _box_only(link):
                continue
            if _held(link, link_pose(model, name, opened).matrix(), origins) > HELD_SHARE:
                links[name] = Link(link.name, link.visuals, (), link.inertial)
    if all(links[name] is model.links[name] for name in links):
        return model
    return RobotModel(model.name, links, model.joints, model.source)


def _box_only(link: Link) -> bool:
    """Whether ``link`` is invisible and collides as boxes only (a URDF's, no stand-in)."""
    boxes = [c for c in link.collisions if c.geometry.kind == "box" and not is_stand_in(c.geometry)]
    return not link.visuals and bool(boxes) and len(boxes) == len(link.collisions)


def _held(link: Link, pose: np.ndarray, points: np.ndarray) -> float:
    """The share of ``points`` (root frame) inside one of ``link``'s boxes at ``pose``."""
    inside = np.zeros(len(points), bool)
    for collision in link.collisions:
        box = pose @ collision.origin.matrix()
        local = (points - box[:3, 3]) @ box[:3, :3]
        half = np.asarray(collision.geometry.size) / 2
        inside |= np.all(np.abs(local) <= half + INSIDE, axis=1)
    return float(inside.mean())
