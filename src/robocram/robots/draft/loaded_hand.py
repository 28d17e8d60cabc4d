"""The model a drafted arm is parked in: its hand as loading will shape it.

Loading grows a gripper's stand-in finger boxes to where the fingers hold and cuts its
palm's back (``robots/grasp_space.py``); the check then opens the gripper where the arm is
parked. A parking pose found on the boxes as read (a cube at each finger's root) put the
Donbot's WSG 50, its fingers grown to the tool frame, into its base when opened. So an
arm whose hand loading changes is parked on the hand as loaded; any other on the model
as read (the same model, the same pose as before).
"""

from __future__ import annotations

import warnings

from robocram.robots.derived_values import derive_arm
from robocram.robots.description import ArmDescription
from robocram.robots.description_check import infer_arm
from robocram.robots.errors import DescriptionError
from robocram.robots.grasp_space import clear_grasp_space
from robocram.robots.model_additions import FrameSpec
from robocram.robots.robot_model import RobotModel


def hand_as_loaded(model: RobotModel, arm: ArmDescription, added: FrameSpec | None) -> RobotModel:
    """``model`` with ``arm``'s hand as loading shapes it (its tool frame ``added``), or
    ``model`` itself where loading leaves the hand as read or cannot derive it."""
    framed = model
    if added is not None and added.name not in model.links:
        framed = model.with_frame(added)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # loading warns about the arm once, not here
            derived = derive_arm(model.name, infer_arm(arm, framed), framed)
    except DescriptionError:
        return model
    shaped = clear_grasp_space(framed, {arm.name: derived})
    return model if shaped is framed else shaped
