"""``base_in_ik`` from the reach envelope's shape: a thin slice or a small reach, not a count."""

from __future__ import annotations

import dataclasses
import warnings
from pathlib import Path

import pytest

from robocram.kinematics import base_in_ik
from robocram.robot_check import description_from
from robocram.robots import LoadedDescription, RobotModel, load_description
from robocram.robots.arm_slice import SMALL_REACH, THIN, arm_slice

ROOT = Path(__file__).resolve().parents[2]
STRETCH = ROOT / "tests" / "data" / "stretch" / "stretch.py"
FILES = {
    "stretch": STRETCH,
    "fetch": ROOT / "tests" / "data" / "fetch" / "fetch.py",
    **{
        n: ROOT / "examples" / "robots" / f"{n}.py"
        for n in (
            "tiago",
            "tiago_pro",
            "talos",
            "z1",
            "so101",
            "panda",
            "baxter",
        )
    },  # fmt: skip
}
WITH_BASE = {"stretch": "planar", "hsrb": "planar", "so101": "small"}
EVERY = ("pr2", "hsrb", "boxy", *FILES)


def _loaded(robot: str) -> LoadedDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        if robot in FILES:
            return load_description(description_from(str(FILES[robot])))
        return load_description(robot)


@pytest.mark.parametrize("robot", EVERY)
def test_base_in_ik_follows_the_envelope_and_keeps_the_earlier_robots(robot: str) -> None:
    """PR2, Boxy, TIAGo off and the HSR on, as before; Stretch on for its slice. The
    SO-101's small reach would take its base along, but it is drafted as a lone arm whose
    base is fixed (issue 37), which IK never moves."""
    desc = _loaded(robot)
    for name, arm in desc.arms.items():
        shape = arm_slice(desc.model, arm)
        why = WITH_BASE.get(robot)
        moves = why is not None and desc.drive != "fixed"
        assert base_in_ik(desc, name) == moves, (robot, name, shape)
        assert shape.planar == (why == "planar"), shape
        assert shape.small == (why == "small"), shape


@pytest.mark.filterwarnings("ignore::robocram.robots.MissingMeshWarning")
def test_a_planar_arm_is_planar_whatever_its_joint_count() -> None:
    """Stretch's URDF without the coupling: eight joints (four telescope segments), one plane."""
    stretch = _loaded("stretch")
    raw = RobotModel.from_file(Path(stretch.urdf), missing_packages_as_boxes=True)
    arm = stretch.arms["arm"]
    joints = tuple(
        j.name for j in raw.chain(arm.base_link or "", arm.end_effector_link) if j.movable
    )
    assert len(joints) == 8
    shape = arm_slice(raw, dataclasses.replace(arm, joints=joints))
    assert shape.flatness < 0.1 < THIN  # about 0.03: the hand moves in the base's y-z plane
    assert shape.reach > SMALL_REACH


def test_a_fixed_base_never_moves_in_ik() -> None:
    hsr = load_description("hsrb")
    assert not base_in_ik(dataclasses.replace(hsr, base_type="fixed"), "arm")
    arm = dataclasses.replace(hsr.arms["arm"], base_in_ik=True)  # set, it wins
    assert base_in_ik(dataclasses.replace(hsr, base_type="fixed", arms={"arm": arm}), "arm")
