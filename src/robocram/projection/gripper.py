"""Grippers in projection: open, close, grip and set positions, attaching what is gripped.

Every motion goes through the arm's gripper description (``ArmDescription.gripper``): each
of its joints moves linearly between its closed and open value, all together, so a
parallel gripper and a hand with coupled fingers open and close alike. A position is a
value of the master (first) joint.

Gripping closes step by step and judges success by contact, not by the closed pose: an
object is held once the gripper's links touch it from opposing sides (two contact normals
more than :data:`OPPOSED` apart), found to within a bisection of the step where that
first happens. The object is attached to the arm's end-effector link there. Objects the
hand does not come near, and static ones like tables, are never gripped. With nothing
held when fully closed, ``GripperClosedCompletely`` is raised, as in CRAM.
"""

from __future__ import annotations

from robocram.execution.failures import GripperClosedCompletely, GripperGoalNotReached
from robocram.projection.errors import ProjectionError
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import ArmDescription, GripperDescription
from robocram.world import WorldObject

TOUCH = 1e-3  # [m] a link this close to an object touches it
OPPOSED = -0.3  # cos: two contact normals over ~107 degrees apart squeeze the object (three
# fingers spaced 120 degrees around an object do)
CLOSING_STEPS = 20  # steps from the current opening to closed
BISECTION_STEPS = 8  # halvings of the step in which the object was first squeezed
NEAR = 0.02  # [m] margin around the hand's bounding box for objects worth testing


def gripper_of(robot: ProjectedRobot, arm: str) -> GripperDescription:
    """The gripper description of ``arm`` (set on every loaded description with one)."""
    gripper = robot.arm(arm).gripper
    if gripper is None:
        raise ProjectionError(
            f"arm {arm!r} of {robot.name} has no gripper; give its ArmDescription "
            "gripper_joints (or gripper=GripperDescription(...))"
        )
    return gripper


def gripper_joints(robot: ProjectedRobot, arm: str) -> tuple[str, ...]:
    """The joints that open and close the gripper of ``arm``, master first."""
    return gripper_of(robot, arm).names


def _set_fraction(robot: ProjectedRobot, arm: str, fraction: float) -> dict[str, float]:
    """Put the gripper ``fraction`` of the way from closed (0) to open (1)."""
    values = gripper_of(robot, arm).at(fraction)
    robot.world.set_joint_states(robot.name, values)
    states = robot.world.joint_states(robot.name)
    return {j: states[j] for j in values}


def _opening(robot: ProjectedRobot, arm: str) -> float:
    """How far open the gripper is now (0 closed, 1 open), within [0, 1]."""
    gripper = gripper_of(robot, arm)
    master = robot.world.joint_states(robot.name)[gripper.names[0]]
    return min(max(gripper.fraction_of(master), 0.0), 1.0)


def open_gripper(robot: ProjectedRobot, arm: str) -> dict[str, float]:
    """Open ``arm``'s gripper fully and release what it holds; return the joint values."""
    release(robot, arm)
    return _set_fraction(robot, arm, 1.0)


def close_gripper(robot: ProjectedRobot, arm: str) -> dict[str, float]:
    """Close ``arm``'s gripper fully (no grip check, nothing attached)."""
    return _set_fraction(robot, arm, 0.0)


def set_gripper(robot: ProjectedRobot, arm: str, position: float) -> dict[str, float]:
    """Set ``arm``'s gripper so that its master joint is at ``position`` [rad | m].

    Raises:
        GripperGoalNotReached: ``position`` lies beyond the closed or open value (the
            nearest of them is set).
    """
    gripper = gripper_of(robot, arm)
    fraction = gripper.fraction_of(float(position))
    reached = _set_fraction(robot, arm, min(max(fraction, 0.0), 1.0))
    if not 0.0 <= fraction <= 1.0:
        master = gripper.joints[0]
        applied = reached[master.name]
        raise GripperGoalNotReached(
            f"gripper goal {position} of {robot.name}'s {arm} arm is outside "
            f"[{min(master.closed, master.open)}, {max(master.closed, master.open)}]; "
            f"moved to {applied}",
            gripper=arm,
            goal=float(position),
            reached=applied,
        )
    return reached


def _arm_links(spec: ArmDescription) -> set[str]:
    return {spec.end_effector_link, spec.tool_frame, *spec.gripper_links, *spec.hand_links}


def release(robot: ProjectedRobot, arm: str) -> list[str]:
    """Detach every object held by ``arm``'s hand; return their names."""
    links = _arm_links(robot.arm(arm))
    held = [o for o, link in robot.world.attachments(robot.name).items() if link in links]
    for name in held:
        robot.world.detach(name)
    return held


def _squeezed(robot: ProjectedRobot, links: set[str], obj: WorldObject) -> bool:
    """Whether ``links`` touch ``obj`` from opposing sides."""
    points = robot.world.contact_points(robot.name, obj, distance=TOUCH)
    normals = [p.normal_on_b for p in points if p.link_a in links and p.distance <= TOUCH]
    return any(
        sum(a * b for a, b in zip(n, m, strict=True)) < OPPOSED
        for i, n in enumerate(normals)
        for m in normals[i + 1 :]
    )


def _near_hand(robot: ProjectedRobot, links: set[str]) -> list[WorldObject]:
    """Movable objects, not held, whose bounding box comes within :data:`NEAR` of the hand."""
    world = robot.world
    boxes = [world.link_aabb(robot.name, link) for link in links]
    low = [min(b[0][k] for b in boxes) - NEAR for k in range(3)]
    high = [max(b[1][k] for b in boxes) + NEAR for k in range(3)]
    held = set(world.attachments(robot.name))
    found = []
    for obj in world.objects():
        if obj.name == robot.name or obj.is_static or obj.name in held:
            continue
        lo, hi = world.aabb(obj)
        if all(lo[k] <= high[k] and hi[k] >= low[k] for k in range(3)):
            found.append(obj)
    return found


def grip(robot: ProjectedRobot, arm: str) -> str:
    """Close ``arm``'s gripper until it squeezes an object, attach it and return its name.

    Raises:
        GripperClosedCompletely: the gripper closed fully without squeezing anything.
    """
    spec = robot.arm(arm)
    links = {
        link for link in (*spec.gripper_links, *spec.hand_links) if link in robot.body.link_index
    }
    candidates = _near_hand(robot, links)
    before = _opening(robot, arm)
    for step in range(1, CLOSING_STEPS + 1):
        fraction = before * (1 - step / CLOSING_STEPS)
        _set_fraction(robot, arm, fraction)
        held = next((o for o in candidates if _squeezed(robot, links, o)), None)
        if held is not None:
            _first_squeeze(
                robot, arm, links, held, fraction, before * (1 - (step - 1) / CLOSING_STEPS)
            )
            robot.world.attach(held, robot.name, spec.end_effector_link)
            return held.name
    closed = robot.world.joint_states(robot.name)[gripper_joints(robot, arm)[0]]
    raise GripperClosedCompletely(
        f"{robot.name}'s {arm} gripper closed on nothing: no movable object was squeezed "
        "between its fingers",
        gripper=arm,
        position=closed,
    )


def _first_squeeze(
    robot: ProjectedRobot,
    arm: str,
    links: set[str],
    obj: WorldObject,
    inside: float,
    outside: float,
) -> float:
    """Bisect the opening between ``inside`` (squeezed) and ``outside`` (not); set the former."""
    for _ in range(BISECTION_STEPS):
        middle = (inside + outside) / 2
        _set_fraction(robot, arm, middle)
        if _squeezed(robot, links, obj):
            inside = middle
        else:
            outside = middle
    _set_fraction(robot, arm, inside)
    return inside
