"""A differential base never moves sideways: not in IK's base motions, not on its paths.

Stretch's and the Fetch's drafts say ``base_type="differential"`` (two wheels on one
axle). Every base step is checked in the base's own frame, at the step's middle heading:
its sideways part must be nil (a Reeds-Shepp arc's chord and a straight drive have none).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Iterator, Sequence
from pathlib import Path

import numpy as np
import pytest

from robocram.execution.failures import NavigationPoseUnreachable
from robocram.kinematics import IKOptions, PlanarBase, forward_kinematics, solve_ik
from robocram.motion import JointTrajectory, plan_base_path, trajectory_listener
from robocram.plans import pick_up
from robocram.projection import ProjectedRobot, simulated_robot
from robocram.projection.navigation import drive
from robocram.robots import LoadedDescription, load_description
from robocram.scenes import tabletop_scene
from robocram.scenes.placement import TABLE_DEPTH
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World
from tests.kitchen_transports import SHARED, Transports

DATA = Path(__file__).resolve().parents[1] / "data"
QUERIES = 40  # seeded IK queries per robot
SIDEWAYS = 1e-3  # [m] a step's sideways part, at most, plus 2 % of its length


def _loaded(path: Path) -> LoadedDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_description(str(path))


@pytest.fixture(scope="module")
def stretch() -> LoadedDescription:
    return _loaded(DATA / "stretch" / "stretch.py")


@pytest.fixture(scope="module")
def fetch() -> LoadedDescription:
    return _loaded(DATA / "fetch" / "fetch.py")


def sideways(poses: Sequence[Sequence[float]]) -> np.ndarray:
    """Per step between ``poses`` (x, y, yaw): the sideways part [m] beyond the allowance."""
    p = np.asarray(poses, dtype=float)
    step = np.diff(p[:, :2], axis=0)
    heading = (p[1:, 2] + p[:-1, 2]) / 2
    lateral = -np.sin(heading) * step[:, 0] + np.cos(heading) * step[:, 1]
    return np.abs(lateral) - 0.02 * np.hypot(step[:, 0], step[:, 1])


def _targets(rng: np.random.Generator, working_yaw: float) -> Iterator[Pose]:
    """Tool poses around the arm's working side, some beyond its reach from where it stands."""
    for _ in range(QUERIES):
        ahead, aside = rng.uniform(0.3, 1.1), rng.uniform(-0.6, 0.6)
        c, s = math.cos(working_yaw), math.sin(working_yaw)
        position = (c * ahead - s * aside, s * ahead + c * aside, rng.uniform(0.5, 1.0))
        yield Pose(position, quat.from_euler(0.0, math.pi / 2, rng.uniform(-math.pi, math.pi)))


@pytest.mark.parametrize(("robot", "arm", "working_yaw"), [
    ("stretch", "arm", -math.pi / 2), ("fetch", "arm", 0.0),
])  # fmt: skip
def test_ik_moves_a_differential_base_along_its_heading_only(
    robot: str, arm: str, working_yaw: float, request: pytest.FixtureRequest
) -> None:
    desc: LoadedDescription = request.getfixturevalue(robot)
    assert desc.drive == "differential"
    holonomic = dataclasses.replace(desc, base_type="holonomic")
    virtual: set[str] = set()

    def seen(values: dict[str, float]) -> bool:
        virtual.update(k for k in values if k.startswith("planar_base"))
        return False

    solved, offsets = 0, {"differential": [], "holonomic": []}
    for seed, target in enumerate(_targets(np.random.default_rng(7), working_yaw)):
        for kind, d in (("differential", desc), ("holonomic", holonomic)):
            options = IKOptions(base=PlanarBase(), random_seed=seed)
            check = seen if d is desc else None
            result = solve_ik(d, arm, target, options=options, collision_check=check)
            if not result.success:
                continue
            motion = result.base_motion
            assert motion is not None
            offsets[kind].append(abs(motion.y))
            if d is not desc:
                continue
            solved += 1
            steps = motion.drive_steps()
            assert (sideways(steps) <= SIDEWAYS).all(), steps
            moved = motion.pose() * forward_kinematics(
                desc, result.joint_positions, desc.arms[arm].tool_frame
            )  # the split motion and the joints together reach the target
            assert moved.position == pytest.approx(target.position, abs=2e-3)
    # the chain is turn, drive, turn: no virtual joint slides sideways
    assert virtual == {"planar_base_turn_joint", "planar_base_x_joint", "planar_base_yaw_joint"}
    assert solved >= 0.9 * QUERIES
    # a sideways offset costs two turns: IK prefers poses along the heading
    assert np.mean(offsets["differential"]) < np.mean(offsets["holonomic"])


def test_base_paths_of_a_differential_base_never_slide(stretch: LoadedDescription) -> None:
    rng = np.random.default_rng(3)
    with World() as world:
        world.bodies.add_floor()
        robot = world.add_robot(stretch)
        for _ in range(12):
            x, y, yaw = rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-3, 3)
            path = plan_base_path(
                RobotHandle.of(world, robot), Pose((x, y, 0.0), quat.from_euler(0, 0, yaw))
            )
            assert path.planner == "reeds_shepp"
            assert (sideways(path.poses) <= SIDEWAYS).all()
            assert (sideways(path.trajectory.positions()) <= SIDEWAYS).all()


def _base_steps(trajectories: list[JointTrajectory]) -> list[np.ndarray]:
    return [sideways(t.positions()) for t in trajectories if t.kind == "base"]


@SHARED  # the session's kitchen transports: one worker runs their modules
@pytest.mark.parametrize("robot", ["stretch", "fetch"])
def test_the_kitchen_transport_drives_without_sliding(
    robot: str, request: pytest.FixtureRequest, kitchen_transports: Transports
) -> None:
    """The session's mug transport (``tests/kitchen_transports.py``), every trajectory it
    executed kept."""
    desc: LoadedDescription = request.getfixturevalue(robot)
    assert desc.drive == "differential"
    run = kitchen_transports(desc, "mug")
    assert run.done.object_name == "mug-1"
    assert run.world.bodies.attached_to("mug-1") is None
    steps = _base_steps(run.executed)
    assert len(steps) >= 2  # to the counter, to the table
    assert all((s <= SIDEWAYS).all() for s in steps)


def test_an_hsr_on_two_wheels_reaches_a_mug_beside_it_without_sliding() -> None:
    """The case that refused "forward, then turn": a mug 30 cm beside the arm's reach."""
    desc = load_description("hsrb")
    scene = tabletop_scene(dataclasses.replace(desc, base_type="differential"))
    world = scene.world
    executed: list[JointTrajectory] = []
    try:
        height = world.pose("mug-1").position[2]
        spot = (world.pose("table").position[0] - TABLE_DEPTH / 2 + 0.15, -0.25, height)
        world.set_pose("mug-1", Pose(spot))
        with trajectory_listener(executed.append), simulated_robot(world, scene.robot):
            pick_up(PoseStamped("map", spot))
        assert world.bodies.attached_to("mug-1") is not None
    finally:
        world.close()
    steps = _base_steps(executed)
    assert steps  # the base moved
    assert all((s <= SIDEWAYS).all() for s in steps)


def test_a_fixed_base_stays_where_it_stands() -> None:
    desc = dataclasses.replace(load_description("pr2"), base_type="fixed")
    with World() as world:
        world.bodies.add_floor()
        robot = ProjectedRobot.of(world, world.add_robot(desc).name)
        drive(robot, Pose())  # where it stands: nothing to do
        with pytest.raises(NavigationPoseUnreachable, match="fixed"):
            drive(robot, Pose((0.5, 0.0, 0.0)))
        assert world.pose(robot.name).position == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
