"""A drafted arm parks stowed: compact, within limits, touching nothing, a telescope retracted.

Without an SRDF the draft searches a stowed pose and keeps it over the sampled one ("wrist
low beside the shoulder") where it touches nothing (checked on the collision meshes) and
is more compact, or where the sampled one touches and the stowed one is about as compact.
"""

from __future__ import annotations

import warnings
from pathlib import Path

from robocram.robots import RobotModel, load_description
from robocram.robots.draft.parking import parking_pose
from robocram.robots.draft.stowing import SLACK, better_parking, judged_parking, stowed_pose
from robocram.robots.self_contacts import SelfContacts
from tests.drafts import drafted

DATA = Path(__file__).resolve().parents[1] / "data"
STRETCH = DATA / "stretch" / "stretch_description" / "urdf" / "stretch_description.urdf"


def _draft(urdf: Path) -> tuple[RobotModel, dict[str, dict[str, float]], dict[str, str]]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        draft = drafted(urdf)
        desc = load_description(draft.description)
    parkings = {k: dict(a.parking) for k, a in draft.description.arms.items()}
    return desc.model, parkings, dict(draft.why)


def test_stretch_parks_stowed_with_its_telescope_retracted() -> None:
    model, parkings, why = _draft(STRETCH)
    parking = parkings["arm"]
    assert parking["joint_arm_l3"] == 0.0  # retracted: the lower limit
    assert why["arms.arm.parking"].startswith("stowed: within limits, the telescope retracted")
    contacts = SelfContacts(model)
    assert not contacts.touches(parking)
    sampled = parking_pose(model, list(parking), "link_wrist_roll")
    # the sampled pose folds the hand back onto the telescope
    assert ("link_arm_l0", "link_straight_gripper") in contacts.meeting(sampled)
    for joint, value in parking.items():
        spec = model.joints[joint]
        assert spec.lower is not None and spec.upper is not None
        assert spec.lower <= value <= spec.upper


def test_the_fetch_parks_stowed_closer_than_touching() -> None:
    model, parkings, why = _draft(DATA / "fetch" / "fetch_description" / "robots" / "fetch.urdf")
    contacts = SelfContacts(model)
    stowed = judged_parking(model, parkings["arm"], "wrist_roll_link", contacts)
    sampled_values = parking_pose(model, list(parkings["arm"]), "wrist_roll_link")
    sampled = judged_parking(model, sampled_values, "wrist_roll_link", contacts)
    assert sampled.touches  # its hand low beside the shoulder meets the base
    assert not stowed.touches
    assert stowed.extent <= sampled.extent + SLACK
    assert "stowed" in why["arms.arm.parking"]


def test_better_parking_weighs_contact_then_compactness() -> None:
    model, parkings, _ = _draft(STRETCH)
    contacts = SelfContacts(model)
    joints = list(parkings["arm"])
    stowed = stowed_pose(model, joints, "link_wrist_roll", contacts)
    assert stowed is not None and not stowed.touches
    sampled = judged_parking(
        model, parking_pose(model, joints, "link_wrist_roll"), "link_wrist_roll", contacts
    )
    assert better_parking(stowed, sampled)
    assert not better_parking(None, sampled)
    assert not better_parking(stowed, stowed)  # not more compact, nothing to mend


def test_the_self_contact_check_leaves_out_adjacent_links_and_default_contacts() -> None:
    pr2 = load_description("pr2")
    contacts = SelfContacts(pr2.model)
    assert not contacts.touches({})  # every joint at zero: the pairs meeting then are left out
    crossed = {"r_shoulder_pan_joint": 0.5, "l_shoulder_pan_joint": -0.5}  # both turned inwards
    assert ("l_elbow_flex_link", "r_elbow_flex_link") in contacts.meeting(crossed)
