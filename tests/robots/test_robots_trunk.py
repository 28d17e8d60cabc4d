"""A trunk: joints every arm and the camera share (TALOS's waist) stay out of the chains."""

from __future__ import annotations

import warnings

from robocram.robots.example_robot_data import example_robot_data_folder
from tests.drafts import drafted

TALOS = example_robot_data_folder() / "talos_data" / "robots" / "talos_full_v2.urdf"


def test_talos_waist_is_a_trunk_not_part_of_the_arms_or_neck() -> None:
    """TALOS's torso_1/torso_2 turn both arms and the head: cut off, the head is a pan-tilt.

    Its head tilts first (head_1_joint, axis y) and then pans (head_2_joint, axis z).
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        draft = drafted(TALOS)
    desc = draft.description
    assert desc.torso_joint is None and desc.neck_arm is None
    assert desc.pan_tilt is not None
    assert (desc.pan_tilt.pan_joint, desc.pan_tilt.tilt_joint) == ("head_2_joint", "head_1_joint")
    assert "pan_tilt" not in draft.doubts
    for side in ("left", "right"):
        arm = desc.arms[side]
        assert arm.base_link == "torso_2_link"
        assert sorted(arm.parking) == [f"arm_{side}_{i}_joint" for i in range(1, 8)]
    assert "torso_1_joint, torso_2_joint" in draft.why["arms"]
