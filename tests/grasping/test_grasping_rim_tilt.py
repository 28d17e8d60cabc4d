"""A palm hand's rim grasps, tilted about the held wall, raise its wrist over the rim.

Flat, the Hey5 lies over the bowl with its wrist at the rim's height: in the kitchen's
open drawer its wrist met the bowl and its forearm the drawer's front (issue 37). The
wrist's place is read from PyBullet's own kinematics, apart from the grasp model.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.grasping import hand_of, object_shape
from robocram.grasping.grasp import Grasp
from robocram.grasping.grasp_model import RIM_TILTS, grasps
from robocram.grasping.object_grasps import candidates_at
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World
from tests.bullet_links import link_frame

TIAGO = "examples/robots/tiago.py"
FAR = ((5.0, 5.0, 0.0), (0.0, 0.0, 0.0, 1.0))


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    world = World()
    world.add_robot(TIAGO)
    world.add_robot("pr2", pose=Pose((-5.0, 5.0, 0.0)))
    world.add_item("bowl-1", "bowl", FAR)
    yield world
    world.close()


def _rims(world: World, robot: str, arm: str) -> list[Grasp]:
    shape = object_shape(world, world.object("bowl-1"))
    return [
        g for g in grasps(shape, hand_of(world.robot(robot).description, arm)) if g.name == "rim"
    ]


def _wrist_in_tool(world: World) -> np.ndarray:
    """The TIAGo's wrist (``arm_7_link``) in its tool frame, by PyBullet, homogeneous."""
    body, client = world.object("tiago").body_id, world.physics.client()
    frames = []
    for link in ("arm_standard_tool_frame", "arm_7_link"):
        position, rotation = link_frame(body, client, link)
        frame = np.eye(4)
        frame[:3, :3], frame[:3, 3] = rotation, position
        frames.append(frame)
    return np.linalg.inv(frames[0]) @ frames[1][:, 3]


def _wrist(grasp: Grasp, wrist_in_tool: np.ndarray) -> np.ndarray:
    """The wrist's place [m, bowl frame] with the tool at ``grasp``."""
    rotation = quat.to_matrix(grasp.tool.orientation)
    return rotation @ wrist_in_tool[:3] + np.asarray(grasp.tool.position)


def test_a_palm_hands_tilted_rim_grasps_raise_its_wrist_over_the_rim(world: World) -> None:
    shape = object_shape(world, world.object("bowl-1"))
    rims = _rims(world, "tiago", "arm")
    flat = [g for g in rims if g.tilt == 0.0]
    tilted = [g for g in rims if g.tilt > 0.0]
    assert len(tilted) == len(flat) * len(RIM_TILTS) == 8
    inside = _wrist_in_tool(world)
    top = shape.high[2]
    for low, high in zip(flat, tilted, strict=True):
        assert (low.turn, low.approach, low.across) == (high.turn, high.approach, high.across)
        before, after = _wrist(low, inside), _wrist(high, inside)
        assert before[2] - top < 0.03  # flat: the wrist's thick housing down at the rim
        # turned 0.3 rad about the wall: the wrist, 0.23 m from the fingers, rises 6 cm
        assert after[2] - before[2] == pytest.approx(0.06, abs=0.015)
        # the fingers stay on the wall: the tool moves by a few centimetres only
        moved = np.subtract(high.tool.position, low.tool.position)
        assert float(np.linalg.norm(moved)) < 0.05


def test_parallel_grippers_keep_their_rim_grasps_flat(world: World) -> None:
    rims = _rims(world, "pr2", "left")
    assert rims and all(g.tilt == 0.0 for g in rims)


def test_each_tilted_rim_grasp_comes_after_the_flat_ones_of_its_side(world: World) -> None:
    desc = world.robot("tiago").description
    shape = object_shape(world, world.object("bowl-1"))
    found = candidates_at(shape, Pose((1.0, 0.0, 0.8)), desc, "arm", Pose(), ("rim",))
    seen: set[tuple[float, float, float]] = set()
    for candidate in found:
        across = tuple(abs(round(c, 6)) for c in candidate.grasp.across)
        if candidate.grasp.tilt == 0.0:
            seen.add(across)  # type: ignore[arg-type]
        else:
            assert across in seen
