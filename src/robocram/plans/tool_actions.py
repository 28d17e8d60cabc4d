"""The tool actions: pouring, wiping, cutting and mixing, with a tool the robot holds.

Each plan reads what it acts on from the knowledge base (poses, boxes, which hand holds
the tool), makes the tool point's curve (:mod:`robocram.plans.tool_paths`) and performs
it as a motion of the ``tools`` resource, which follows it as a checked, timed tool path
with only the named contacts allowed (the sponge on the surface it wipes, the knife in
what it cuts; the spoon and the pouring cup touch nothing). docs/tool_actions.md.
"""

from __future__ import annotations

import math

from robocram.designators import a
from robocram.designators.tool_answers import CuttingAnswer, PouringAnswer, ToolPathAnswer
from robocram.execution import perform
from robocram.knowledge.world_predicates import OBJECT_POSE
from robocram.logic import current_kb
from robocram.plans.errors import PlanArgumentError, PlanSetupError
from robocram.plans.known_robot import current_robot
from robocram.plans.tool_coverage import covered_share
from robocram.plans.tool_failures import ToolPathIncomplete
from robocram.plans.tool_objects import (
    WALL,
    ObjectBox,
    ensure_uncovered,
    holding_arm,
    object_box,
)
from robocram.plans.tool_paths import coverage_path, saw_path, spiral_path, tilt_path
from robocram.plans.tool_results import CuttingResult, MixingResult, PouringResult, WipingResult
from robocram.plans.tool_stands import from_a_stand
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.tf.quaternion import Quaternion

PRESS = 0.002  # [m] the sponge is pressed this far into the surface it wipes
WIPE_DEPTH = 0.005  # [m] the deepest the sponge may go into the surface
LIP_HEIGHT = 0.03  # [m] the pouring lip above the target's rim
POUR_ANGLE = 2.1  # [rad] the source is tilted this far (120 degrees)
STIR_MARGIN = 0.012  # [m] the spoon's head keeps this far from the container's wall
STIR_HEIGHT = 0.012  # [m] the spoon's tip above the container's bottom
EDGE_ABOVE = 0.004  # [m] the knife's edge stops this far above the object's underside
NEEDED = 0.9  # share of a pour's tilt or a stir's spiral reached, or of a region wiped,
# for the action to count as done (below it: ToolPathIncomplete, never a quiet result)


def _incomplete(action: str, what: str, reached: float, needed: float, why: str) -> None:
    """Raise :class:`ToolPathIncomplete` when ``reached`` falls short of ``needed``."""
    if reached < needed:
        raise ToolPathIncomplete(
            f"{action}: {what} {reached:.0%}, {needed:.0%} needed"
            + (f"; stopped by {why}" if why else ""),
            action=action,
            fraction=reached,
            needed=needed,
            stopped_by=why,
        )


def _reached_part(path: list[Pose], fraction: float) -> list[Pose]:
    """The poses of ``path`` a tool path reached at ``fraction`` (the first is moved to
    before the path is planned; the fraction counts along the rest)."""
    if fraction >= 1.0:
        return path
    return path[: 1 + int(fraction * (len(path) - 2) + 1e-9)]


def _bottom_point(box: ObjectBox) -> Pose:
    """The middle of the box's underside, in the object's frame."""
    middle = box.middle
    return Pose((middle[0], middle[1], box.low[2]))


def _upright(orientation: Quaternion) -> Quaternion:
    """A held tool's orientation stood upright, its heading kept: the paths start from the
    tool as it is used (a hand that carried it parked may hold it tilted)."""
    return quat.from_euler(0.0, 0.0, quat.to_euler(orientation)[2])


def _unit(v: Vector3) -> Vector3:
    norm = math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2)
    if norm < 1e-9:
        raise PlanSetupError(f"a tool action needs a direction, got the zero vector {v}")
    return (v[0] / norm, v[1] / norm, v[2] / norm)


def _tool_path(
    arm: str, path: list[Pose], tool: str, point: Pose, contacts: object, needed: float = 0.0
) -> object:
    return perform(
        a.motion(
            type="moving-tool-path", arm=arm, path=path, tool=tool, tool_point=point,
            contacts=contacts, needed=needed,
        )
    )  # fmt: skip


def pour(source: str, target: str, amount: float, arm: str | None = None) -> PouringResult:
    """Pour ``amount`` [ml] from the held ``source`` into ``target``: the source's lip goes
    over the target's opening and the source tilts about it, then turns upright again.

    Raises:
        TargetCovered: something lies on the target's opening (named).
        ToolNotHeld: no hand holds ``source``.
        ToolPathIncomplete: the tilt stopped short of :data:`NEEDED` (the source is
            turned upright again first).
    """
    arm = holding_arm("pouring", source, arm)
    ensure_uncovered("pouring", target)
    tgt = object_box("pouring", target)
    centre = tgt.point(tgt.middle[0], tgt.middle[1], tgt.high[2])
    return from_a_stand("pouring", centre, arm, lambda: _pour_here(source, target, amount, arm))


def _pour_here(source: str, target: str, amount: float, arm: str) -> PouringResult:
    """The pour from where the robot stands (the lip on the side across its reach)."""
    src, tgt = object_box("pouring", source), object_box("pouring", target)
    robot = OBJECT_POSE.first(current_kb(), object=current_robot().name)
    base = robot.pose.position if robot is not None else (0.0, 0.0, 0.0)
    reach = _unit((src.pose.position[0] - base[0], src.pose.position[1] - base[1], 0.0))
    toward = (-reach[1], reach[0], 0.0)  # the lip on the side, across the hand's reach
    standing = _upright(src.pose.orientation)
    local = quat.rotate(quat.conjugate(standing), toward)
    radius = 0.5 * min(src.size[0], src.size[1])
    middle = src.middle
    lip = Pose((middle[0] + radius * local[0], middle[1] + radius * local[1], src.high[2]))
    centre = tgt.point(tgt.middle[0], tgt.middle[1], tgt.high[2])
    offset = 0.25 * tgt.inner_radius()
    at = (centre[0] - offset * toward[0], centre[1] - offset * toward[1], centre[2] + LIP_HEIGHT)
    path = tilt_path(at, standing, toward, POUR_ANGLE, src.size[2])
    poured = perform(
        a.motion(
            type="pouring", arm=arm, path=path, source=source, tool_point=lip,
            destination=target, amount=float(amount), needed=NEEDED,
        )
    )  # fmt: skip
    if not isinstance(poured, PouringAnswer):
        raise PlanSetupError(f"pouring answered {poured!r}, not a PouringAnswer")
    back = list(reversed(_reached_part(path, poured.path.fraction)[:-1]))
    if back:  # upright again, along the part of the tilt it reached
        _tool_path(arm, back, source, lip, [])
    _incomplete("pouring", "the tilt reached", poured.path.fraction, NEEDED, poured.path.stopped_by)
    return PouringResult(
        source, target, float(amount), poured.path.fraction, poured.particles, poured.landed,
        poured.spilled,
    )  # fmt: skip


def wipe(
    surface: str,
    region: tuple[tuple[float, float], tuple[float, float]],
    tool: str,
    arm: str | None = None,
) -> WipingResult:
    """Wipe ``region`` (``((x, y), (size_x, size_y))`` [m] in map, on top of ``surface``)
    with the held ``tool`` (a sponge), its underside pressed lightly on the surface along
    lawn-mower lanes; the result says the share of the region it covered.

    Raises:
        ToolNotHeld: no hand holds ``tool``.
        ToolPathIncomplete: less than :data:`NEEDED` of the region was covered.
        PlanSetupError: the region is not two pairs of numbers, or is empty.
    """
    arm = holding_arm("wiping", tool, arm)
    (x, y), size = _region(region)
    top_box = object_box("wiping", surface)
    top = top_box.point(top_box.middle[0], top_box.middle[1], top_box.high[2])[2]
    return from_a_stand(
        "wiping", (x, y, top), arm, lambda: _wipe_here(surface, (x, y), size, top, tool, arm)
    )


def _wipe_here(
    surface: str,
    at: tuple[float, float],
    size: tuple[float, float],
    top: float,
    tool: str,
    arm: str,
) -> WipingResult:
    """The wipe from where the robot stands, the sponge flat and square to the region's
    lanes, turned by the fewest quarter turns from how the hand holds it (a sponge held
    askew leaves the corners between lanes unwiped: Boxy, carried round the table, wiped
    83 % with it turned 115 degrees)."""
    sponge = object_box("wiping", tool)
    quarters = round(quat.to_euler(sponge.pose.orientation)[2] / (math.pi / 2))
    sx, sy = sponge.size[0], sponge.size[1]
    footprint = (sy, sx) if quarters % 2 else (sx, sy)
    centre = Pose((at[0], at[1], top))
    orientation = quat.from_euler(0.0, 0.0, quarters * math.pi / 2)
    path = coverage_path(centre, size, footprint, top - PRESS, orientation)
    contacts = [[surface, WIPE_DEPTH]]
    done = _tool_path(arm, path, tool, _bottom_point(sponge), contacts, 1.0)  # every lane
    if not isinstance(done, ToolPathAnswer):
        raise PlanSetupError(f"moving-tool-path answered {done!r}, not a ToolPathAnswer")
    own = (sponge.size[0], sponge.size[1])  # turned with the tool at each pose
    covered = covered_share(centre, size, own, top, done.tool_poses)
    _incomplete("wiping", "the region covered", covered, NEEDED, done.stopped_by)
    return WipingResult(surface, tool, covered, done.fraction)


def _region(region: object) -> tuple[tuple[float, float], tuple[float, float]]:
    try:
        flat = [float(v) for pair in region for v in pair]  # type: ignore[attr-defined]
        if len(flat) != 4 or len(region) != 2:  # type: ignore[arg-type]
            raise PlanArgumentError(region)
        values = (flat[0], flat[1], flat[2], flat[3])
    except (TypeError, ValueError) as err:
        raise PlanSetupError(
            f"a region to wipe is ((x, y), (size_x, size_y)) [m] in map, got {region!r}"
        ) from err
    if not (values[2] > 0.0 and values[3] > 0.0):
        raise PlanSetupError(f"a region to wipe needs a positive size, got {region!r}")
    return (values[0], values[1]), (values[2], values[3])


def cut(object: str, tool: str, slices: int, arm: str | None = None) -> CuttingResult:  # noqa: A002
    """Cut ``object`` into ``slices`` slices of equal width with the held ``tool`` (a knife):
    at each cut the blade saws down across the object's longest horizontal axis.

    Raises:
        ToolNotHeld: no hand holds ``tool``.
        ToolPathIncomplete: the knife did not go through every cut.
        PlanSetupError: ``slices`` is not a whole number of at least 2.
    """
    if isinstance(slices, bool) or not isinstance(slices, int) or slices < 2:
        raise PlanSetupError(f"cutting makes a whole number of slices >= 2, got {slices!r}")
    obj = object
    arm = holding_arm("cutting", tool, arm)
    box = object_box("cutting", obj)
    top = box.point(box.middle[0], box.middle[1], box.high[2])
    return from_a_stand("cutting", top, arm, lambda: _cut_here(obj, tool, slices, arm))


def _cut_here(obj: str, tool: str, slices: int, arm: str) -> CuttingResult:
    """The cuts from where the robot stands, the blade as the hand holds the knife."""
    box, knife = object_box("cutting", obj), object_box("cutting", tool)
    axis = 0 if box.size[0] >= box.size[1] else 1
    length = box.size[axis]
    offsets = [-length / 2 + length * k / slices for k in range(1, slices)]
    points = []
    for c in offsets:
        local = list(box.middle)
        local[axis] += c
        points.append(box.point(local[0], local[1], local[2]))
    along = _unit(
        quat.rotate(box.pose.orientation, (1.0, 0.0, 0.0) if axis == 0 else (0.0, 1.0, 0.0))
    )
    blade = _unit((-along[1], along[0], 0.0))
    forward = quat.rotate(knife.pose.orientation, (1.0, 0.0, 0.0))
    if blade[0] * forward[0] + blade[1] * forward[1] < 0.0:
        blade = (-blade[0], -blade[1], 0.0)
    upright = quat.from_euler(0.0, 0.0, math.atan2(blade[1], blade[0]))
    top = box.point(box.middle[0], box.middle[1], box.high[2])[2]
    bottom = box.point(box.middle[0], box.middle[1], box.low[2])[2] + EDGE_ABOVE
    edge = Pose(((knife.low[0] + 3 * knife.high[0]) / 4, knife.middle[1], knife.low[2]))
    path = saw_path(points, blade, top, bottom, upright)
    contacts = [[obj, box.size[2] + 0.01]]
    done = perform(
        a.motion(
            type="cutting", arm=arm, path=path, tool=tool, tool_point=edge, contacts=contacts,
            item=obj, cuts=offsets, needed=NEEDED,
        )
    )  # fmt: skip
    if not isinstance(done, CuttingAnswer):
        raise PlanSetupError(f"cutting answered {done!r}, not a CuttingAnswer")
    made = len(done.cuts_made) / len(offsets)
    _incomplete("cutting", "the cuts made", made, 1.0, done.path.stopped_by)
    widths = tuple(_width(name, axis) for name in done.slices)
    return CuttingResult(obj, tool, done.slices, widths, done.path.fraction)


def _width(name: str, axis: int) -> float:
    return object_box("cutting", name).size[axis]


def mix(container: str, tool: str, arm: str | None = None, turns: float = 2.0) -> MixingResult:
    """Stir inside ``container`` with the held ``tool`` (a spoon): its tip goes down into
    the middle, spirals out ``turns`` turns and back, clear of the wall, and comes out.

    Raises:
        ToolNotHeld: no hand holds ``tool``.
        ToolPathIncomplete: the spiral stopped short of :data:`NEEDED`.
        PlanSetupError: the tool's head does not fit inside the container.
    """
    arm = holding_arm("mixing", tool, arm)
    bowl, spoon = object_box("mixing", container), object_box("mixing", tool)
    head = 0.5 * math.hypot(spoon.size[0], spoon.size[1])
    radius = bowl.inner_radius() - head - STIR_MARGIN
    if radius <= 0.0:
        raise PlanSetupError(
            f"mixing: {tool!r} ({2 * head:.3f} m across) does not fit inside {container!r} "
            f"({2 * bowl.inner_radius():.3f} m within its walls)"
        )
    centre = bowl.point(bowl.middle[0], bowl.middle[1], bowl.low[2] + WALL + STIR_HEIGHT)
    clearance = bowl.inner_radius() - head - radius

    def stir() -> MixingResult:
        spoon = object_box("mixing", tool)  # as the hand holds it now
        path = spiral_path(centre, radius, turns, _upright(spoon.pose.orientation))
        done = _tool_path(arm, path, tool, _bottom_point(spoon), [], NEEDED)
        if not isinstance(done, ToolPathAnswer):
            raise PlanSetupError(f"moving-tool-path answered {done!r}, not a ToolPathAnswer")
        _incomplete("mixing", "the spiral reached", done.fraction, NEEDED, done.stopped_by)
        return MixingResult(container, tool, turns, radius, clearance, done.fraction)

    return from_a_stand("mixing", centre, arm, stir)
