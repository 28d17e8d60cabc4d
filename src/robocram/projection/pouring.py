"""Pouring in projection: the source's contents as particles, tilted out under physics.

``pour`` is the ``pour`` command of the ``tools`` module. The tilt path is planned first,
on the world without contents (a checked, timed tool path of the cup's lip). Then the
contents appear as small spheres (:data:`ML_PER_PARTICLE` millilitres each) stacked inside
the source, at seeded spots, and settle there; the arm follows the planned trajectory
while physics runs (the robot's joints set at every physics step, the source riding in
the hand), and the particles settle again afterwards. Each particle counts as landed
when its centre is inside the target's opening (the cylinder within its walls, up to its
rim plus a margin), else as spilled. The particles stay where they settled (objects of
type ``particle``, named ``<source>-contents-<k>``): the target's contents, and what
spilled.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from robocram.designators.tool_answers import PouringAnswer
from robocram.execution import checkpoint
from robocram.grasping import shape_of
from robocram.motion import JointTrajectory
from robocram.motion.whole_body_scene import put_configuration
from robocram.projection.errors import ProjectionError
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.tool_motion import PathPose, answer, plan_from_start, tool_grip
from robocram.projection.trajectory_follower import follow
from robocram.tf import Pose, PoseLike
from robocram.world import ShapeSpec, World
from robocram.world.kinematic_body import kinematic

ML_PER_PARTICLE = 2.0  # [ml] of contents one particle stands for
PARTICLE_RADIUS = 0.005  # [m]
PARTICLE_MASS = 0.002  # [kg]
MAX_PARTICLES = 400  # more is refused (each is a body stepped by physics)
WALL = 0.006  # [m] a container's wall and bottom, kept clear when filling and counting
RIM_MARGIN = 0.02  # [m] a particle this far above the target's rim still counts as in it
SETTLE_BEFORE = 0.3  # [s] of physics for the particles to settle in the source
SETTLE_TIME = 1.5  # [s] at most for the poured particles to come to rest
PARTICLE_COLOUR = (0.95, 0.85, 0.55, 1.0)


@dataclass(frozen=True)
class Opening:
    """A container's inside, in its own frame: the radius within the walls [m], the
    bottom's top and the rim's height [m]."""

    radius: float
    bottom: float
    rim: float
    centre: tuple[float, float]

    @classmethod
    def of(cls, world: World, name: str) -> Opening:
        """The opening of object ``name`` from its box in its own frame."""
        shape = shape_of(world, world.object(name))
        return cls(shape.radius - WALL, shape.low[2] + WALL, shape.high[2], shape.centre)

    def holds(self, point_in_object: tuple[float, float, float]) -> bool:
        """Whether a point (the object's frame) is inside, up to the rim and its margin."""
        x, y, z = point_in_object
        r = math.hypot(x - self.centre[0], y - self.centre[1])
        return r <= self.radius and self.bottom - WALL <= z <= self.rim + RIM_MARGIN


def particle_count(amount: float) -> int:
    """How many particles stand for ``amount`` [ml] (at least one).

    Raises:
        ProjectionError: the amount is not a positive number, or needs too many particles.
    """
    if not isinstance(amount, int | float) or not amount > 0.0 or math.isinf(amount):
        raise ProjectionError(f"an amount to pour is a positive number of ml, got {amount!r}")
    count = max(1, round(amount / ML_PER_PARTICLE))
    if count > MAX_PARTICLES:
        raise ProjectionError(
            f"pouring {amount} ml needs {count} particles of {ML_PER_PARTICLE} ml; projection "
            f"simulates at most {MAX_PARTICLES} ({MAX_PARTICLES * ML_PER_PARTICLE} ml)"
        )
    return count


def particle_spots(opening: Opening, count: int, seed: int) -> list[tuple[float, float, float]]:
    """``count`` spots (the container's frame) stacked in layers inside ``opening``, each
    a little off its lattice point (seeded)."""
    rng = random.Random(seed)
    pitch = 2.2 * PARTICLE_RADIUS
    reach = opening.radius - PARTICLE_RADIUS - 0.001
    layer = [
        (i * pitch, j * pitch)
        for i in range(-10, 11) for j in range(-10, 11)
        if math.hypot(i * pitch, j * pitch) <= reach
    ]  # fmt: skip
    if not layer:
        raise ProjectionError(f"a container {2 * opening.radius:.3f} m wide holds no particle")
    spots = []
    for k in range(count):
        x, y = layer[k % len(layer)]
        z = opening.bottom + PARTICLE_RADIUS * (1.2 + 2.2 * (k // len(layer)))
        jitter = 0.15 * PARTICLE_RADIUS
        spots.append(
            (
                opening.centre[0] + x + rng.uniform(-jitter, jitter),
                opening.centre[1] + y + rng.uniform(-jitter, jitter),
                z,
            )
        )
    return spots


def pour(
    robot: ProjectedRobot,
    arm: str,
    path: Sequence[PathPose],
    source: str,
    tool_point: PoseLike | None,
    target: str,
    amount: float,
    needed: float = 0.0,
) -> PouringAnswer:
    """Tilt ``source`` (held by ``arm``) along ``path`` of its ``tool_point`` (the lip)
    over ``target``; its ``amount`` [ml] of contents poured as particles. A tilt planned
    to less than ``needed`` of the path is refused before the contents appear."""
    count = particle_count(amount)
    world = robot.world
    world.object(target)  # an unknown target is named before anything moves
    grip = tool_grip(robot, arm, source, tool_point)
    planned = plan_from_start(robot, grip, path, needed=needed)
    seed = robot.motion.seed
    names = _fill(world, source, count, seed)
    with kinematic(world, source):  # the hand moves it; the grains do not push it
        world.physics.simulate(SETTLE_BEFORE, stop_check=checkpoint)
        _follow_with_physics(robot, planned.motion.trajectory)
        _settle(world, names)
    landed = _landed(world, target, names)
    return PouringAnswer(answer(robot, grip, planned), count, landed, count - landed)


def _fill(world: World, source: str, count: int, seed: int) -> list[str]:
    """Particles inside ``source`` as it stands; their names."""
    pose = world.pose(source)
    names = []
    for k, spot in enumerate(particle_spots(Opening.of(world, source), count, seed)):
        name = f"{source}-contents-{k}"
        spec = ShapeSpec("sphere", (2 * PARTICLE_RADIUS,) * 3, PARTICLE_MASS, PARTICLE_COLOUR)
        world.add_object(name, "particle", spec, pose * Pose(spot))
        names.append(name)
    return names


def _follow_with_physics(robot: ProjectedRobot, trajectory: JointTrajectory) -> None:
    """Follow ``trajectory`` one physics step at a time (joints set by interpolating its
    points), then report it as followed."""
    world = robot.world
    points = trajectory.points
    times = np.array([p.time_from_start for p in points])
    positions = np.array([p.positions for p in points])
    steps = max(1, math.ceil(trajectory.duration / world.time_step))
    for k in range(1, steps + 1):
        checkpoint()
        t = min(k * world.time_step, trajectory.duration)
        values = [float(np.interp(t, times, positions[:, j])) for j in range(positions.shape[1])]
        put_configuration(robot.handle, trajectory.joint_names, values)  # base too, if whole-body
        world.physics.step()
    follow(robot, trajectory)


def _settle(world: World, names: list[str]) -> None:
    """Run physics until no particle moves more than 1 mm in 0.1 s, or :data:`SETTLE_TIME`."""
    look = max(1, round(0.1 / world.time_step))
    before = [world.pose(n).position for n in names]
    for _ in range(math.ceil(SETTLE_TIME / (look * world.time_step))):
        for _ in range(look):
            checkpoint()
            world.physics.step()
        now = [world.pose(n).position for n in names]
        if all(math.dist(a, b) <= 0.001 for a, b in zip(before, now, strict=True)):
            return
        before = now


def _landed(world: World, target: str, names: list[str]) -> int:
    """How many of the particles ``names`` are inside ``target``'s opening."""
    opening = Opening.of(world, target)
    inverse = world.pose(target).inverse()
    return sum(opening.holds((inverse * world.pose(n)).position) for n in names)
