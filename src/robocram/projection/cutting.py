"""Cutting in projection: the knife saws through, and the object becomes its slices.

``cut`` is the ``cut`` command of the ``tools`` module. The knife (held) follows its
sawing path, allowed to touch only what the plan names (the object it cuts), each within
its depth. A planned cut counts as made when the knife's edge went down through the
object there: an executed pose of the tool point within :data:`CUT_TOLERANCE` of the
cut's offset along the object's axis, and within :data:`CUT_TOLERANCE` of the object's
underside. Then the object's body is replaced by one box per slice between the cuts made
(and its ends), named ``<object>-slice-<k>``, each of the object's type with
``_slice`` appended and its share of the mass; the boxes span the object's box in its own
frame (a loaf is cut as the box round it).
"""

from __future__ import annotations

from collections.abc import Sequence

from robocram.designators.tool_answers import CuttingAnswer
from robocram.grasping import ObjectShape, shape_of
from robocram.projection.errors import ProjectionError
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.tool_motion import (
    PathPose,
    allowances,
    answer,
    plan_from_start,
    tool_grip,
)
from robocram.projection.trajectory_follower import follow
from robocram.tf import Pose, PoseLike
from robocram.world import ShapeSpec, World

CUT_TOLERANCE = 0.01  # [m] how near a cut's plane and the underside the edge must come
SLICE_COLOUR = (0.8, 0.6, 0.3, 1.0)
AXES = "xyz"


def cut(
    robot: ProjectedRobot,
    arm: str,
    path: Sequence[PathPose],
    tool: str,
    tool_point: PoseLike | None,
    contacts: object,
    obj: str,
    cuts: Sequence[float],
    needed: float = 0.0,
) -> CuttingAnswer:
    """Saw ``obj`` with ``tool`` (held by ``arm``) along ``path`` of its ``tool_point``
    (the edge), at ``cuts`` (offsets [m] along the object's longest axis, from its
    middle); the object becomes the slices between the cuts made. A path planned to less
    than ``needed`` is refused before the knife moves along it."""
    world = robot.world
    shape = shape_of(world, world.object(obj))
    axis = _longest(shape)
    offsets = _checked_cuts(obj, shape, axis, cuts)
    grip = tool_grip(robot, arm, tool, tool_point)
    checked = planned_against(robot)
    planned = plan_from_start(robot, grip, path, allowances(tool, contacts), needed)
    follow(robot, planned.motion.trajectory, checked)
    followed = answer(robot, grip, planned)
    made = _made(world, obj, shape, axis, offsets, followed.tool_poses)
    slices = _sliced(world, obj, shape, axis, made) if made else ()
    return CuttingAnswer(followed, made, slices)


def _longest(shape: ObjectShape) -> int:
    size = shape.size
    return max(range(3), key=lambda k: size[k])


def _middle(shape: ObjectShape, axis: int) -> float:
    return 0.5 * (shape.low[axis] + shape.high[axis])


def _checked_cuts(
    obj: str, shape: ObjectShape, axis: int, cuts: Sequence[float]
) -> tuple[float, ...]:
    """The cuts, sorted, each strictly inside the object along its axis.

    Raises:
        ProjectionError: a cut is no number or lies outside the object.
    """
    half = 0.5 * shape.size[axis]
    out = []
    for c in cuts:
        if not isinstance(c, int | float) or not -half < c < half:
            raise ProjectionError(
                f"a cut of {obj!r} is an offset [m] along its {AXES[axis]} axis strictly "
                f"between {-half:.3f} and {half:.3f}, got {c!r}"
            )
        out.append(float(c))
    return tuple(sorted(out))


def _made(
    world: World,
    obj: str,
    shape: ObjectShape,
    axis: int,
    offsets: tuple[float, ...],
    poses: Sequence[Pose],
) -> tuple[float, ...]:
    """The cuts the edge went through: near the cut's plane and near the underside."""
    inverse = world.pose(obj).inverse()
    local = [(inverse * p).position for p in poses]
    middle, bottom = _middle(shape, axis), shape.low[2]
    return tuple(
        c for c in offsets
        if any(
            abs(q[axis] - middle - c) <= CUT_TOLERANCE and q[2] - bottom <= CUT_TOLERANCE
            for q in local
        )
    )  # fmt: skip


def _sliced(
    world: World, obj: str, shape: ObjectShape, axis: int, made: tuple[float, ...]
) -> tuple[str, ...]:
    """Replace ``obj`` by boxes between ``made`` cuts; the slices' names, in axis order."""
    handle = world.object(obj)
    pose = world.pose(obj)
    mass = getattr(handle.spec, "mass", None) or 0.0  # [kg] none given: static slices
    middle = _middle(shape, axis)
    bounds = [shape.low[axis], *(middle + c for c in made), shape.high[axis]]
    total = shape.high[axis] - shape.low[axis]
    world.remove(obj)
    names = []
    for k, (a, b) in enumerate(zip(bounds, bounds[1:], strict=False)):
        size = list(shape.size)
        size[axis] = b - a
        centre = [0.5 * (lo + hi) for lo, hi in zip(shape.low, shape.high, strict=True)]
        centre[axis] = 0.5 * (a + b)
        name = f"{obj}-slice-{k + 1}"
        spec = ShapeSpec("box", (size[0], size[1], size[2]), mass * (b - a) / total, SLICE_COLOUR)
        middle_at = (centre[0], centre[1], centre[2])
        world.add_object(name, f"{handle.type}_slice", spec, pose * Pose(middle_at))
        names.append(name)
    return tuple(names)
