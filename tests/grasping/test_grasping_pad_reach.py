"""Where a hand's pads end along its approach: Tracy's behind its tool frame, the PR2's past.

Tracy (tests/data/zoo, drafted): its Robotiq 85's pads end 18 mm behind its drafted tool
frame (36 mm with the hand open), so it gets deep rim grasps; the PR2's fingertips reach
19 mm past its tool frame, so its rim grasps stay as they were. Judged in raw PyBullet:
a slab across the approach whose near face lies a margin behind the measured end, over
the fingers' stroke, touches no finger at any opening; one a margin before it touches one.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.grasping import grasps, hand_of
from robocram.grasping.grasp_model import PADS_BEHIND_DEEP
from robocram.grasping.object_shape import ObjectShape
from robocram.robots import RobotDescription, load_description
from robocram.tf import quaternion as quat
from robocram.world import World
from tests.drafts import drafted_module

TRACY = Path(__file__).resolve().parents[1] / "data" / "zoo" / "tracy" / "tracy.urdf"
TRACY_BEHIND = 0.018  # [m] its pads' farthest reach, behind the tool frame (closed)
PR2_PAST = 0.019  # [m] the PR2's fingertips' farthest reach past its tool frame
TOLERANCE = 0.002  # [m]
MARGIN = 0.002  # [m] the judge's slab this far clear of the measured end, or into it
OPENINGS = np.linspace(0.0, 1.0, 11)  # the judge's openings (finer than the measurement's)
SLAB = 0.15  # [m] the judge's slab's half depth
BOWL = ObjectShape("bowl-1", (-0.08, -0.08, 0.0), (0.08, 0.08, 0.06), wall=0.006)


@pytest.fixture(scope="module")
def tracy(tmp_path_factory: pytest.TempPathFactory) -> RobotDescription:
    module = tmp_path_factory.mktemp("tracy") / "tracy.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(TRACY, module)
        return load_description(str(module))


def _links(client: int, body: int) -> dict[str, int]:
    infos = [
        pybullet.getJointInfo(body, i, physicsClientId=client)
        for i in range(pybullet.getNumJoints(body, physicsClientId=client))
    ]
    return {info[12].decode(): info[0] for info in infos}


def _slab_touches(desc: RobotDescription, arm: str, behind: float) -> list[bool]:
    """Per opening of the judge's, whether a slab across the approach (1 m wide, 0.3 m
    deep), its near face ``behind`` [m] behind the tool frame, touches a finger."""
    spec = desc.arms[arm]
    assert spec.gripper is not None
    approach = np.asarray(hand_of(desc, arm).approach)
    touches = []
    with World() as world:
        name = world.add_robot(desc).name
        client, body = world.physics.client(), world.object(name).body_id
        links = _links(client, body)
        shape = pybullet.createCollisionShape(
            pybullet.GEOM_BOX, halfExtents=(SLAB, 0.5, 0.5), physicsClientId=client
        )
        slab = pybullet.createMultiBody(0.0, shape, physicsClientId=client)
        for opening in OPENINGS:
            world.set_joint_states(name, spec.gripper.at(float(opening)))
            state = pybullet.getLinkState(
                body, links[spec.tool_frame], computeForwardKinematics=True, physicsClientId=client
            )
            along = np.array(pybullet.getMatrixFromQuaternion(state[5])).reshape(3, 3) @ approach
            side = np.cross(along, (0.0, 0.0, 1.0) if abs(along[2]) < 0.9 else (1.0, 0.0, 0.0))
            side /= np.linalg.norm(side)
            frame = np.column_stack([along, side, np.cross(along, side)])
            centre = np.asarray(state[4]) + (SLAB - behind) * along
            pybullet.resetBasePositionAndOrientation(
                slab, centre.tolist(), quat.from_matrix(frame), physicsClientId=client
            )
            touches.append(
                any(
                    point[8] < 0.0
                    for finger in spec.gripper_links
                    for point in pybullet.getClosestPoints(
                        body, slab, 0.0, linkIndexA=links[finger], physicsClientId=client
                    )
                )
            )
    return touches


def test_tracys_pads_end_behind_its_tool_frame_and_it_gets_deep_rim_grasps(
    tracy: RobotDescription,
) -> None:
    hand = hand_of(tracy, "arm_1")
    assert hand.pads_behind == pytest.approx(TRACY_BEHIND, abs=TOLERANCE)
    assert hand.pads_behind >= PADS_BEHIND_DEEP
    assert not any(_slab_touches(tracy, "arm_1", TRACY_BEHIND - MARGIN))
    assert any(_slab_touches(tracy, "arm_1", TRACY_BEHIND + MARGIN))
    assert sum(g.deeper > 0 for g in grasps(BOWL, hand, ("rim",))) == 8


def test_the_pr2s_fingertips_reach_past_its_tool_frame_and_get_no_deep_grasps() -> None:
    pr2 = load_description("pr2")
    for arm in ("left", "right"):
        hand = hand_of(pr2, arm)
        assert hand.pads_behind == pytest.approx(-PR2_PAST, abs=TOLERANCE)
        assert all(g.deeper == 0 for g in grasps(BOWL, hand, ("rim",)))
    assert not any(_slab_touches(pr2, "left", -PR2_PAST - MARGIN))
    assert any(_slab_touches(pr2, "left", -PR2_PAST + MARGIN))
