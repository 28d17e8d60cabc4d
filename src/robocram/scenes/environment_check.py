"""``robocram env check``: drive every part of an environment description once, a report card.

Each container's joint is moved to its opening and back: the handle must go out of the
front (the description's ``front``) by the drawer's opening, or out of the door's plane,
and come back. Each surface gets a test item dropped over its middle: after a second of
physics it must rest on that link at the surface's height. One line per check.
"""

from __future__ import annotations

import importlib.util
import math
from dataclasses import dataclass
from pathlib import Path

from robocram.scenes.environment_description import (
    ContainerDescription,
    EnvironmentDescription,
    SurfaceDescription,
)
from robocram.scenes.environment_model import loadable_urdf
from robocram.scenes.errors import SceneError
from robocram.tf import Pose
from robocram.world import World

HEIGHT_TOLERANCE = 0.02  # [m] a test item rests this close to the surface's height
DOOR_MIN_OUT = 0.05  # [m] an opened door's handle comes at least this far out of the front
TEST_ITEM = "bowl"  # the catalogue item dropped on each surface


@dataclass(frozen=True)
class CheckLine:
    """One check: what was driven, whether it passed, and what was seen (or the fix)."""

    part: str
    passed: bool
    detail: str


@dataclass(frozen=True)
class EnvironmentCard:
    """The report card of one environment description."""

    name: str
    lines: tuple[CheckLine, ...]

    @property
    def passed(self) -> bool:
        """Whether every check passed."""
        return all(line.passed for line in self.lines)

    def render(self) -> str:
        """One line per check, then a summary line."""
        out = [f"{self.name}:"]
        out += [f"  {'ok  ' if c.passed else 'FAIL'} {c.part}: {c.detail}" for c in self.lines]
        good = sum(c.passed for c in self.lines)
        out.append(f"{good} of {len(self.lines)} checks pass")
        return "\n".join(out)


def environment_from(spec: str | Path) -> EnvironmentDescription:
    """The description a ``.py`` file's ``description()`` returns.

    Raises:
        SceneError: no such file, or it defines no ``description()`` returning one.
    """
    path = Path(spec)
    if not path.is_file():
        raise SceneError(f"no file {path}; `robocram env draft URDF -o FILE` writes one")
    loader = importlib.util.spec_from_file_location(f"robocram_env_{path.stem}", path)
    if loader is None or loader.loader is None:
        raise SceneError(f"cannot load {path} as a Python module")
    module = importlib.util.module_from_spec(loader)
    loader.loader.exec_module(module)
    value = getattr(module, "description", None)
    value = value() if callable(value) else value
    if not isinstance(value, EnvironmentDescription):
        raise SceneError(f"{path}: description() gives no EnvironmentDescription")
    return value


def check_environment(desc: EnvironmentDescription) -> EnvironmentCard:
    """Load ``desc`` alone in a world and drive each container and surface once."""
    world = World()
    try:
        world.bodies.add_floor()
        loadable = loadable_urdf(desc.urdf, desc.stand_ins, package_paths=desc.package_paths)
        world.add_urdf(desc.name, loadable, type="environment")
        lines = [_check_container(world, desc.name, c) for c in desc.containers]
        lines += [_check_surface(world, desc.name, s) for s in desc.surfaces]
    finally:
        world.close()
    return EnvironmentCard(desc.name, tuple(lines))


def _check_container(world: World, env: str, c: ContainerDescription) -> CheckLine:
    part = f"{c.kind} {c.link} ({c.joint})"
    closed = world.link_pose(env, c.handle).position
    world.set_joint_states(env, {c.joint: c.opening})
    opened = world.link_pose(env, c.handle).position
    world.set_joint_states(env, {c.joint: 0.0})
    back = world.link_pose(env, c.handle).position
    out = (opened[0] - closed[0]) * math.cos(c.front) + (opened[1] - closed[1]) * math.sin(c.front)
    wanted = abs(c.opening) - 0.01 if c.kind == "drawer" else DOOR_MIN_OUT
    if math.dist(closed, back) > 1e-4:
        return CheckLine(part, False, "the handle did not come back when closed")
    if out < wanted:
        return CheckLine(
            part,
            False,
            f"opening to {c.opening} moves the handle {out:.3f} m out of the front "
            f"(yaw {c.front:.2f} rad), not {wanted:.2f}; fix front or opening",
        )
    return CheckLine(part, True, f"opens {out:.3f} m out of its front, closes again")


def _check_surface(world: World, env: str, s: SurfaceDescription) -> CheckLine:
    part = f"surface {s.link}"
    low, high = world.contacts.link_aabb(env, s.link)
    x, y = (low[0] + high[0]) / 2, (low[1] + high[1]) / 2
    item = world.add_item(f"test-{s.link}", TEST_ITEM, Pose((x, y, s.height + 0.05)))
    try:
        world.physics.simulate(1.0)
        bottom = world.aabb(item)[0][2]
        on = sorted({p.link_b for p in world.contacts.contact_points(item, env) if p.link_b})
    finally:
        world.remove(item)
    if s.link not in on or abs(bottom - s.height) > HEIGHT_TOLERANCE:
        return CheckLine(
            part,
            False,
            f"a {TEST_ITEM} dropped at ({x:.2f}, {y:.2f}) came to rest at {bottom:.3f} m on "
            f"{on or 'nothing'}, not on its top at {s.height:.3f} m; fix the height or the link",
        )
    return CheckLine(part, True, f"a {TEST_ITEM} rests on it at {bottom:.3f} m")
