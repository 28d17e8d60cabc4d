"""Draft an environment description from its URDF, as ``robot draft`` does for robots.

- **Containers**: every prismatic joint (a drawer) and revolute joint (a door) with some
  range. The drawer is the link that moves; a door's things lie in the body it hangs on.
  The handle is a link fixed to the moving one, named like a handle, else the smallest
  box sticking out furthest in front; none found is a doubt. The front is where the handle
  goes as the joint starts to open (within :data:`SNAP` of a quarter turn: that turn);
  the opening is the joint's far limit less a margin.
- **Surfaces**: upward faces of collision boxes that never move, at least
  :data:`MIN_SURFACE_SIDE` wide, between :data:`SURFACE_HEIGHTS`, and not covered by
  another box.
- **Stand-ins** for links whose mesh files are missing: a drawer's open box, a table's
  or counter's top (:mod:`robocram.scenes.stand_in_draft`); surfaces are then looked for
  on them too.
- Doubts (a joint without a handle, a link whose size hides in a mesh) become
  ``# TODO doubt:`` comments in the source.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from robocram.scenes.environment_description import (
    ContainerDescription,
    EnvironmentDescription,
    SurfaceDescription,
)
from robocram.scenes.environment_model import Box, EnvironmentModel, EnvJoint
from robocram.scenes.stand_in_draft import DraftedStandIn, draft_stand_ins, drawer_fronts
from robocram.tf import Pose
from robocram.tf import quaternion as quat

MIN_SURFACE_SIDE = 0.25  # [m] the narrower side of a top things are put on
SURFACE_HEIGHTS = (0.35, 1.3)  # [m] tops outside these: plinths, shelves out of reach, walls
COVER_GAP = 0.03  # [m] a box this close above a top covers it
DRAWER_MARGIN = 0.05  # [m] a drawer opens this much short of its limit
DOOR_MARGIN = 0.2  # [rad] a door opens this much short of its limit
MIN_RANGE = 0.05  # [m | rad] joints moving less are no containers (a panel's play)
HANDLE_SIZE = 0.4  # [m] a handle found by geometry is smaller than this on every side
SNAP = math.radians(10.0)  # [rad] a front this close to a quarter turn is taken as one
FRONT_STEP = 1e-3  # [m | rad] joint step over which the handle's way out is measured


@dataclass(frozen=True)
class EnvironmentDraft:
    """A drafted description, why each part was chosen, and the doubts left."""

    description: EnvironmentDescription
    reasons: dict[str, str] = field(default_factory=dict)  # link -> why
    doubts: list[str] = field(default_factory=list)
    stand_ins: tuple[DraftedStandIn, ...] = ()  # with why and doubt, as in the description

    def source(self, module_file: Path | None = None) -> str:
        """The draft as a ready-to-edit Python module defining ``description()``."""
        # the source writer is the robot drafter's (pinocchio, coal): loaded when written
        from robocram.scenes.environment_source import environment_source

        return environment_source(
            self.description, self.reasons, self.doubts, self.stand_ins, module_file
        )


def draft_environment(
    urdf: str | Path, name: str | None = None, package_paths: Iterable[str | Path] = ()
) -> EnvironmentDraft:
    """Draft the description of the environment in ``urdf``; ``package_paths``: folders
    holding the packages its ``package://`` meshes name (``ROS_PACKAGE_PATH`` and a
    package beside the URDF are searched too)."""
    path = Path(urdf)
    paths = tuple(Path(p).expanduser().resolve() for p in package_paths)
    model = EnvironmentModel.from_file(path, paths)
    reasons: dict[str, str] = {}
    doubts: list[str] = []
    containers = list(_containers(model, reasons, doubts))
    drawers = [(model.joints[c.link], c.handle) for c in containers if c.kind == "drawer"]
    stand_ins = tuple(draft_stand_ins(model, drawer_fronts(model, drawers)))
    model = model.with_stand_ins(s.stand_in for s in stand_ins)
    inside = {c.link for c in containers}  # a cupboard's shelves are inside it, no surface
    tops: dict[str, str] = {}
    surfaces = [s for s in _surfaces(model, tops) if s.link not in inside]
    reasons.update((s.link, tops[s.link]) for s in surfaces)
    unsized = sorted(k for k, n in model.meshes.items() if n and not model.boxes.get(k))
    if unsized:
        doubts.append(
            f"{len(unsized)} links have mesh shapes only, so no surface was looked for on "
            f"them ({', '.join(unsized[:6])}{', ...' if len(unsized) > 6 else ''}); add "
            "SurfaceDescription(link, height) and a StandIn for any you put things on"
        )
    description = EnvironmentDescription(
        name or model.name,
        path,
        tuple(surfaces),
        tuple(containers),
        package_paths=paths,
        stand_ins=tuple(s.stand_in for s in stand_ins),
    )
    return EnvironmentDraft(description, reasons, doubts, stand_ins)


def _containers(
    model: EnvironmentModel, reasons: dict[str, str], doubts: list[str]
) -> Iterator[ContainerDescription]:
    for joint in model.joints.values():  # in the URDF's order
        if joint.type not in ("prismatic", "revolute"):
            continue
        if joint.upper - joint.lower < MIN_RANGE:
            doubts.append(f"{joint.name}: moves {joint.upper - joint.lower:.3f} only; left out")
            continue
        handle, how = _handle(model, joint)
        if handle is None and joint.type == "revolute":
            doubts.append(
                f"{joint.name}: a revolute joint with no handle (a knob, a tap?); left out"
            )
            continue
        drawer = joint.type == "prismatic"
        link = joint.child if drawer else joint.parent
        if handle is None:
            handle, how = joint.child, "none found: pulled by the drawer itself"
            doubts.append(f"{joint.name}: no handle found on {joint.child}; it is pulled by itself")
        opening = _opening(joint)
        reasons[link] = (
            f"{'prismatic' if drawer else 'revolute'} {joint.name} moves {joint.child}; "
            f"handle {handle} ({how})"
        )
        yield ContainerDescription(
            link,
            joint.name,
            handle,
            "drawer" if drawer else "door",
            opening,
            _front(model, joint, handle, opening),
        )


def _handle(model: EnvironmentModel, joint: EnvJoint) -> tuple[str | None, str]:
    fixed = model.fixed_subtree(joint.child)[1:]
    named = [link for link in fixed if "handle" in link.lower()]
    if named:
        return named[0], "by name"
    small = [
        link
        for link in fixed
        if model.boxes.get(link) and all(max(b.size) < HANDLE_SIZE for b in model.boxes[link])
    ]
    if not small:
        return None, ""
    out = _way_out(model, joint, joint.child)
    best = max(
        small, key=lambda k: sum(a * b for a, b in zip(model.pose(k).position, out, strict=True))
    )
    return best, "by geometry: the small part furthest in front"


def _opening(joint: EnvJoint) -> float:
    far = joint.upper if abs(joint.upper) >= abs(joint.lower) else joint.lower
    margin = DRAWER_MARGIN if joint.type == "prismatic" else DOOR_MARGIN
    size = max(abs(far) - margin, abs(far) / 2)
    return round(math.copysign(size, far), 4)


def _way_out(
    model: EnvironmentModel, joint: EnvJoint, link: str, at: Pose | None = None
) -> tuple[float, float, float]:
    """How a point ``at`` (in ``link``'s frame) moves as ``joint`` starts to open."""
    far = joint.upper if abs(joint.upper) >= abs(joint.lower) else joint.lower
    step = math.copysign(FRONT_STEP, far)
    here = (model.pose(link) * (at or Pose())).position
    there = (model.pose(link, {joint.name: step}) * (at or Pose())).position
    return (there[0] - here[0], there[1] - here[1], there[2] - here[2])


def _front(model: EnvironmentModel, joint: EnvJoint, handle: str, opening: float) -> float:
    """Yaw [rad] of the way out of the front: where the handle goes as the joint opens.

    For a door, the middle of its panel (its first box) is taken: the handle sticks out
    of the panel, and its path would tilt the front by that much.
    """
    panel = model.boxes.get(joint.child)
    if joint.type == "revolute" and panel:
        dx, dy, _ = _way_out(model, joint, joint.child, panel[0].origin)
    else:
        dx, dy, _ = _way_out(model, joint, handle)
    if math.hypot(dx, dy) < 1e-9:  # a handle on the hinge's axis: take the link's x
        x_axis = quat.rotate(model.pose(handle).orientation, (1.0, 0.0, 0.0))
        dx, dy = x_axis[0], x_axis[1]
    yaw = math.atan2(dy, dx)
    quarter = round(yaw / (math.pi / 2)) * (math.pi / 2)
    front = quarter if abs(yaw - quarter) < SNAP else yaw
    return round(math.pi if front <= -math.pi + 1e-9 else front, 4)


def _top(model: EnvironmentModel, link: str, box: Box) -> tuple[float, Pose, float, float] | None:
    """``(height, centre pose, side x, side y)`` of a box's upward face, or None."""
    pose = model.pose(link) * box.origin
    up = quat.rotate(pose.orientation, (0.0, 0.0, 1.0))
    if abs(up[2]) < 0.99:
        return None
    sx, sy, sz = box.size
    return pose.position[2] + sz / 2, pose, sx, sy


BoxFrame = tuple[str, Pose, tuple[float, float, float]]  # link, box_T_root, size [m]


def _box_frames(model: EnvironmentModel) -> list[BoxFrame]:
    """Every box as ``(link, root_T_box inverted, size)``: computed once for all the
    faces :func:`_covered` asks about (a link's pose walks its chain)."""
    return [
        (link, (model.pose(link) * box.origin).inverse(), box.size)
        for link, boxes in model.boxes.items()
        for box in boxes
    ]


def _covered(
    frames: list[BoxFrame],
    link: str,
    height: float,
    centre: Pose,
) -> bool:
    x, y, _ = centre.position
    for other, box_T_root, size in frames:
        if other == link:
            continue
        local = (box_T_root * Pose((x, y, height + COVER_GAP / 2))).position
        if all(abs(c) <= s / 2 + 1e-6 for c, s in zip(local, size, strict=True)):
            return True
    return False


def _surfaces(model: EnvironmentModel, reasons: dict[str, str]) -> Iterator[SurfaceDescription]:
    low, high = SURFACE_HEIGHTS
    frames = _box_frames(model)
    for link, boxes in model.boxes.items():  # in the URDF's order: the KB's order
        if model.moved_by_joint(link):
            continue
        tops = [t for b in boxes if (t := _top(model, link, b)) is not None]
        tops = [t for t in tops if min(t[2], t[3]) >= MIN_SURFACE_SIDE and low <= t[0] <= high]
        tops = [t for t in tops if not _covered(frames, link, t[0], t[1])]
        if tops:
            height, _, sx, sy = max(tops, key=lambda t: t[0])
            reasons[link] = f"an upward face {sx:.2f} x {sy:.2f} m at {height:.3f} m"
            yield SurfaceDescription(link, round(height, 4))
