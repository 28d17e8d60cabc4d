"""The drafted SO-100 and the rise at its shoulder, as raw PyBullet has them: shared by the
tests of where its tabletop and workcell put things (its shoulder_lift sits 0.10 m above
its shoulder_pan, along the pan's axis, and reaches no farther out for it)."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pybullet

from robocram.robots import example_robot_data_folder
from robocram.scenes.placement import PAST_RISE_SHARE
from tests.bullet_links import link_indices
from tests.drafts import drafted_module

SO100 = "so_arm_description/urdf/so100.urdf"
FOREARMS = 0.311  # [m] the lift joint to the wrist, stretched (the URDF's origins, by hand)
Point = tuple[float, float, float]


def drafted_so100(folder: Path) -> str:
    """The SO-100's draft, with no edits, written as a description file in ``folder``."""
    module = folder / "so100.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        urdf = example_robot_data_folder() / SO100
        drafted_module(urdf, module)
    return str(module)


def rise(body: int, client: int) -> tuple[Point, Point, float]:
    """The pan joint's place, the top of the rise over it (the pan's axis is vertical) and
    the reach from there that the scenes keep to: :data:`PAST_RISE_SHARE` of the forearms
    plus the lift's offset across the axis."""
    links = link_indices(body, client)
    pan = pybullet.getLinkState(body, links["shoulder"], physicsClientId=client)[4]
    lift = pybullet.getLinkState(body, links["upper_arm"], physicsClientId=client)[4]
    top = (pan[0], pan[1], lift[2])
    room = PAST_RISE_SHARE * (FOREARMS + math.hypot(lift[0] - pan[0], lift[1] - pan[1]))
    return tuple(pan), top, room
