"""Stand-in boxes keep out of a gripper's grasp space (``robots/grasp_space.py``, issue 35).

The drafted Fetch's meshes are missing; its tool frame is its ``gripper_link``, whose
stand-in box (and its wrist's) sat on the tool frame, so every grasp put the palm 46-79 mm
into a mug and a drawer's handle, and its finger cubes closed 11 mm apart over a bowl's
rim. Judged on the loaded world by raw PyBullet: link bounds and closest points.
"""

from __future__ import annotations

import gc
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.robots import LoadedDescription, RobotModel, load_description
from robocram.robots.grasp_space import clear_grasp_space
from robocram.world import World
from tests.drafts import drafted_module

FETCH = Path(__file__).resolve().parents[1] / "data" / "fetch" / "fetch.py"


@pytest.fixture(scope="module")
def fetch() -> Iterator[tuple[World, LoadedDescription]]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # its missing meshes
        desc = load_description(str(FETCH))
        world = World()
        world.add_robot(desc, name="fetch")
    yield world, desc
    world.close()


def _link_state(world: World, link: str) -> tuple[np.ndarray, np.ndarray]:
    """The link frame's position and rotation matrix, asked of PyBullet."""
    obj = world.object("fetch")
    state = pybullet.getLinkState(
        obj.body_id, obj.link_index[link], computeForwardKinematics=True,
        physicsClientId=world.physics.client(),
    )  # fmt: skip
    rotation = np.reshape(pybullet.getMatrixFromQuaternion(state[5]), (3, 3))
    return np.asarray(state[4]), rotation


def test_the_hand_ends_half_the_opening_behind_the_tool_frame(
    fetch: tuple[World, LoadedDescription],
) -> None:
    world, desc = fetch
    arm = desc.arms["arm"]
    assert arm.gripper is not None and arm.gripper.max_opening == pytest.approx(0.1, abs=1e-6)
    tool, rotation = _link_state(world, arm.tool_frame)
    approach = rotation[:, 0]  # the draft's convention: x along the approach
    obj = world.object("fetch")
    hand = [link for link in arm.hand_links if link not in arm.gripper_links]
    assert {"wrist_roll_link", "gripper_link"} <= set(hand)
    for link in hand:
        if not pybullet.getCollisionShapeData(obj.body_id, obj.link_index[link],
                                              physicsClientId=world.physics.client()):  # fmt: skip
            continue  # the palm's box lay wholly in the grasp space: dropped
        low, high = pybullet.getAABB(obj.body_id, obj.link_index[link],
                                     physicsClientId=world.physics.client())  # fmt: skip
        corners = np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1])
                            for z in (low[2], high[2])])  # fmt: skip
        ahead = float(np.max((corners - tool) @ approach))
        assert ahead <= -0.05 + 0.002, link  # Bullet's margin grows a box by ~1 mm


def test_the_closed_fingers_meet(fetch: tuple[World, LoadedDescription]) -> None:
    world, desc = fetch
    arm = desc.arms["arm"]
    assert arm.gripper is not None
    obj = world.object("fetch")
    with world.snapshots.stored_state():
        world.set_joint_states("fetch", arm.gripper.at(0.0))
        left, right = (obj.link_index[link] for link in arm.gripper_links)
        near = pybullet.getClosestPoints(obj.body_id, obj.body_id, 0.05, left, right,
                                         physicsClientId=world.physics.client())  # fmt: skip
    assert min(p[8] for p in near) == pytest.approx(0.0, abs=0.003)


def test_a_robot_with_its_meshes_is_left_alone() -> None:
    pr2 = load_description("pr2")
    assert clear_grasp_space(pr2.model, pr2.arms) is pr2.model


def test_loading_again_shares_the_cut_model(fetch: tuple[World, LoadedDescription]) -> None:
    """The cut model is kept with the parsed one: a second load builds no new kinematics."""
    _, desc = fetch
    gc.collect()  # the memo holds the parse weakly: the cut model must hold it
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        again = load_description(str(FETCH))
    assert again.model is desc.model
    assert load_description(desc).model is desc.model  # a loaded description, loaded again


def test_a_five_fingered_hands_stand_in_fingers_keep_their_size(tmp_path: Path) -> None:
    """Armar6's fingers (no meshes) curl side by side round what its palm holds: grown to
    a middle plane lying on their row, they met the mug before the palm did."""
    urdf = Path(__file__).resolve().parents[1] / "data" / "zoo" / "armar6" / "armar6.urdf"
    module = tmp_path / "armar6.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(urdf, module)
        desc = load_description(module)
        raw = RobotModel.from_file(urdf, missing_packages_as_boxes=True)
    for arm in desc.arms.values():
        assert len(arm.gripper_links) == 14  # five fingers: three links each, the thumb two
        for finger in arm.gripper_links:
            sizes = [c.geometry.size for c in desc.model.links[finger].collisions]
            assert sizes == [c.geometry.size for c in raw.links[finger].collisions]
