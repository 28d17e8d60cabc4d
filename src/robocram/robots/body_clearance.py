"""Where an arm's wrist is clear of the robot's own body: the rigid part no joint moves.

An arm mounted on the side of a base (a UR arm on an omnidirectional platform) turns all
the way round, so its wrist gets ahead of its shoulder as often as beside it; but ahead,
the base is in the way: no table can stand there. The working direction counts only wrist
positions outside the body's footprint (``robots/arm_envelope.py``).
"""

from __future__ import annotations

import itertools

import numpy as np
from numpy.typing import NDArray

from robocram.robots.link_centre import link_box
from robocram.robots.model_pose import link_pose
from robocram.robots.robot_model import RobotModel
from robocram.tf import Pose

BODY_MARGIN = 0.05  # [m] a wrist nearer the body than this is in its way


def body_links(model: RobotModel) -> set[str]:
    """The root link and the links fixed to it (the body no joint moves)."""
    body = {model.root_link}
    for joint in model.joints.values():  # parents come before their children in a URDF
        if joint.type == "fixed" and joint.parent in body:
            body.add(joint.child)
    return body


def body_boxes(model: RobotModel) -> NDArray[np.float64]:
    """(n, 2, 3): the root-frame bounds of each body link's collision shapes, grown by
    :data:`BODY_MARGIN` (kept with the model)."""
    return model.derived(_body_boxes)


def _body_boxes(model: RobotModel) -> NDArray[np.float64]:
    boxes = []
    for name in body_links(model):
        box = link_box(model.links[name])
        if box is None:
            continue
        where = link_pose(model, name)
        corners = np.array(
            [
                (where * Pose((x, y, z))).position
                for x, y, z in itertools.product(*zip(*box, strict=True))
            ]
        )
        boxes.append((corners.min(axis=0) - BODY_MARGIN, corners.max(axis=0) + BODY_MARGIN))
    return np.array(boxes, dtype=float).reshape(-1, 2, 3)


def beyond_body(model: RobotModel, points: NDArray[np.float64]) -> NDArray[np.bool_] | None:
    """Per point (n, 3; root frame): whether it lies beyond the body's footprint (all its
    boxes seen from above, grown by :data:`BODY_MARGIN`) ahead, left, right and behind
    (n, 4; the order of ``arm_envelope.QUARTERS``): where a table the arm works at could
    stand. None for a robot without a body of shapes."""
    boxes = body_boxes(model)
    if not len(boxes):
        return None
    low, high = boxes[:, 0, :2].min(axis=0), boxes[:, 1, :2].max(axis=0)
    x, y = points[:, 0], points[:, 1]
    return np.stack([x > high[0], y > high[1], y < low[1], x < low[0]], axis=1)
