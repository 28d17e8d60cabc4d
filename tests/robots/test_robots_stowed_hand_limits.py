"""An arm parks stowed although its hand's uncoupled fingers meet one another at their limits.

The TIAGo's Hey5 hand has no <mimic>: the stowing search opens and closes it by setting
every hand joint to a limit, where its fingers cross one another wherever the arm is. Those
meetings used to make every stowed candidate "touch", so the draft kept the sampled pose
with the arm 0.49 m ahead of the base at an open drawer's height. Pairs inside the hand
say nothing of where the arm parks and are left out of the search.
"""

from __future__ import annotations

import warnings

import pybullet
import pytest

from robocram.robots import draft_description, example_robot_data_folder, load_description
from robocram.robots.description import RobotDescription
from robocram.robots.self_contacts import SelfContacts

URDF = example_robot_data_folder() / "tiago_description" / "robots" / "tiago.urdf"
BASE_FRONT = 0.253  # [m] the TIAGo's base_link reaches this far ahead of its origin
TUCKED = 0.1  # [m] the parked arm sticks out past the base's front by this at most


@pytest.fixture(scope="module")
def tiago() -> RobotDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_description(draft_description(URDF).description)


def test_the_hands_own_meetings_do_not_count_for_the_arm(tiago: RobotDescription) -> None:
    model = tiago.model
    assert model is not None
    contacts = SelfContacts(model)
    arm = tiago.arms["arm"]
    hand = {
        j.name: j.upper
        for j in model.joints.values()
        if j.child in arm.hand_links and j.movable and j.upper is not None
    }
    assert contacts.touches(hand)  # the fingers at their upper limits cross one another
    assert not contacts.touches(hand, frozenset((arm.end_effector_link, *arm.hand_links)))


def test_the_drafted_arm_parks_tucked_and_clear(tiago: RobotDescription) -> None:
    arm = tiago.arms["arm"]
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(tiago.urdf), useFixedBase=True, physicsClientId=client)
        links = {}
        for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
            info = pybullet.getJointInfo(body, i, physicsClientId=client)
            links[info[12].decode()] = i
            if info[1].decode() in arm.parking:
                pybullet.resetJointState(
                    body, i, arm.parking[info[1].decode()], physicsClientId=client
                )
        moving = [links[n] for n in (*arm.links, *arm.hand_links) if n in links]
        front = max(pybullet.getAABB(body, i, physicsClientId=client)[1][0] for i in moving)
        base = links["base_link"]
        gaps = [
            p[8]
            for i in moving
            for p in pybullet.getClosestPoints(body, body, 0.05, i, base, physicsClientId=client)
        ]
    finally:
        pybullet.disconnect(client)
    assert front < BASE_FRONT + TUCKED  # was 0.49 m with the sampled pose
    assert min(gaps, default=1.0) > 0.0  # the parked arm clear of the base
