"""Grippers in projection: open, close, grip and set positions, attaching what is gripped.

Opening goes to the gripper joints' upper limits and lets go of what the arm holds;
closing goes to the lower limits. Gripping decides by geometry whether something is
between the fingers: the closed fingers are tested for penetration with each movable
object (static ones like tables are never gripped). The deepest such object is held: the
fingers close only until they touch it (found by bisection) and it is attached to the
arm's end-effector link. With nothing between the fingers the gripper ends up closed and
``GripperClosedCompletely`` is raised, as in CRAM.
"""

from __future__ import annotations

from collections.abc import Iterable

from robocram.execution.failures import GripperClosedCompletely, GripperGoalNotReached
from robocram.projection.errors import ProjectionError
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import ArmDescription
from robocram.world import WorldObject

GRIP_DEPTH = 1e-3  # [m] closing must push the fingers this much deeper into an object
BISECTION_STEPS = 12


def gripper_joints(robot: ProjectedRobot, arm: str) -> tuple[str, ...]:
    """The joints that open and close the gripper of ``arm``."""
    spec = robot.arm(arm)
    if not spec.gripper_joints:
        raise ProjectionError(f"arm {arm!r} of {robot.name} has no gripper joints")
    return spec.gripper_joints


def _set_gripper(robot: ProjectedRobot, arm: str, where: str | float) -> dict[str, float]:
    world = robot.world
    values: dict[str, float] = {}
    for joint in gripper_joints(robot, arm):
        limits = world.joint_limits(robot.name, joint)
        if where == "open":
            values[joint] = limits.upper
        elif where == "close":
            values[joint] = limits.lower
        else:
            values[joint] = float(where)
    clamped = world.set_joint_states(robot.name, values)
    reached = {j: world.joint_states(robot.name)[j] for j in values}
    if clamped:
        c = clamped[0]
        raise GripperGoalNotReached(
            f"gripper goal {c.requested} of {robot.name}'s {arm} arm is outside "
            f"[{c.lower}, {c.upper}]; moved to {c.applied}",
            gripper=arm,
            goal=c.requested,
            reached=c.applied,
        )
    return reached


def open_gripper(robot: ProjectedRobot, arm: str) -> dict[str, float]:
    """Open ``arm``'s gripper fully and release what it holds; return the joint values."""
    release(robot, arm)
    return _set_gripper(robot, arm, "open")


def close_gripper(robot: ProjectedRobot, arm: str) -> dict[str, float]:
    """Close ``arm``'s gripper fully (no grip check, nothing attached)."""
    return _set_gripper(robot, arm, "close")


def set_gripper(robot: ProjectedRobot, arm: str, position: float) -> dict[str, float]:
    """Set ``arm``'s gripper joints to ``position`` [rad | m].

    Raises:
        GripperGoalNotReached: ``position`` was outside the limits (the clamped value is set).
    """
    return _set_gripper(robot, arm, position)


def _arm_links(spec: ArmDescription) -> set[str]:
    return {spec.end_effector_link, spec.tool_frame, *spec.gripper_links, *spec.hand_links}


def release(robot: ProjectedRobot, arm: str) -> list[str]:
    """Detach every object held by ``arm``'s hand; return their names."""
    links = _arm_links(robot.arm(arm))
    held = [o for o, link in robot.world.attachments(robot.name).items() if link in links]
    for name in held:
        robot.world.detach(name)
    return held


def _penetration(robot: ProjectedRobot, links: Iterable[str], obj: WorldObject) -> float:
    """Smallest signed distance [m] between ``links`` and ``obj`` (< 0: penetrating)."""
    best = GRIP_DEPTH
    for link in links:
        points = robot.world.contact_points(robot.name, obj, link_a=link, distance=GRIP_DEPTH)
        best = min([best, *(p.distance for p in points)])
    return best


def _candidates(robot: ProjectedRobot) -> list[WorldObject]:
    held = set(robot.world.attachments(robot.name))
    return [
        o
        for o in robot.world.objects()
        if o.name != robot.name and not o.is_static and o.name not in held
    ]


def grip(robot: ProjectedRobot, arm: str) -> str:
    """Close ``arm``'s gripper on the object between its fingers and attach it; return its name.

    Raises:
        GripperClosedCompletely: nothing is between the fingers; the gripper is closed.
    """
    spec = robot.arm(arm)
    fingers = [link for link in spec.gripper_links if link in robot.body.link_index]
    joint = gripper_joints(robot, arm)[0]
    opened = robot.world.joint_states(robot.name)[joint]
    candidates = _candidates(robot)
    at_open = {o.name: _penetration(robot, fingers, o) for o in candidates}
    closed = close_gripper(robot, arm)[joint]
    depth = {o.name: _penetration(robot, fingers, o) for o in candidates}
    gripped = [
        o for o in candidates if depth[o.name] < 0 and depth[o.name] < at_open[o.name] - GRIP_DEPTH
    ]
    if not gripped:
        raise GripperClosedCompletely(
            f"{robot.name}'s {arm} gripper closed on nothing: no movable object is between "
            f"its fingers",
            gripper=arm,
            position=closed,
        )
    target = min(gripped, key=lambda o: depth[o.name])
    _close_until_touching(robot, arm, fingers, target, closed, opened)
    robot.world.attach(target, robot.name, spec.end_effector_link)
    return target.name


def _close_until_touching(
    robot: ProjectedRobot,
    arm: str,
    fingers: list[str],
    obj: WorldObject,
    closed: float,
    opened: float,
) -> float:
    """Bisect the gripper opening between ``closed`` and ``opened`` to where fingers touch."""
    inside, outside = closed, opened
    for _ in range(BISECTION_STEPS):
        middle = (inside + outside) / 2
        _set_gripper(robot, arm, middle)
        if _penetration(robot, fingers, obj) < 0:
            inside = middle
        else:
            outside = middle
    _set_gripper(robot, arm, outside)
    return outside
