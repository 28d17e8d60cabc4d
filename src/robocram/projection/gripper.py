"""Grippers in projection: open, close, grip and set positions, attaching what is gripped.

Every motion goes through the arm's gripper description (``ArmDescription.gripper``): each
of its joints moves linearly between its closed and open value, all together, so a
parallel gripper and a hand with coupled fingers open and close alike. A position is a
value of the master (first) joint.

Each motion is a checked, timed trajectory (``joint_motion.py``, kind ``gripper``): the
fingers' way is checked against the world as an arm's is, contacts they start with (a
hand round a handle) allowed; a way that runs into something fails with
``GripperPathBlocked`` before the fingers move.

Closing stops where the fingers squeeze something, as a real gripper does: where the
gripper's links first touch one object from opposing sides (two contact normals more than
:data:`OPPOSED` apart), found by probing the closing in steps and bisecting the step where
that first happens; the fingers then close to there, touching what they squeeze (those
contacts are allowed, and stored with the trajectory bounded to 5 mm). Gripping
squeezes only movable objects and attaches the one squeezed to the arm's end-effector
link; with none squeezed, the fingers close as closing does and
``GripperClosedCompletely`` is raised, as in CRAM. Closing without gripping
closes fully, or, when something is in the way, stops where the fingers squeeze it or
first touch it (a handle's face), and attaches nothing. A suction hand (no fingers) only
releases, moves nothing and holds what its tool frame touches (``suction.py``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection

from robocram.execution import checkpoint
from robocram.execution.failures import (
    GripperClosedCompletely,
    GripperGoalNotReached,
    GripperMetOneSide,
    GripperPathBlocked,
    ManipulationPathBlocked,
)
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH, HandContact
from robocram.projection.errors import ProjectionError
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.suction import suction_grip
from robocram.robots import ArmDescription, GripperDescription
from robocram.tf import Vector3
from robocram.world import WorldObject

TOUCH = 1e-3  # [m] a link this close to an object touches it
CLOSED_GAP = 1e-3  # [m] fingers closer than this when closed meet: nothing is between them
OPPOSED = -0.3  # cos: two contact normals over ~107 degrees apart squeeze the object (three
# fingers spaced 120 degrees around an object do)
CLOSING_STEPS = 20  # steps from the current opening to closed
BISECTION_STEPS = 8  # halvings of the step in which the object was first squeezed
SINK = HAND_CONTACT_DEPTH - 0.001  # [m] a finger this deep in what it grips stops the
# closing: the other side must then be within the hand's bound (5 mm), else the grip fails
CENTRING_REACH = 0.05  # [m] how far the other side of a one-sided grip is looked for
PART_WAY = (0.75, 0.5, 0.35)  # of the full opening, tried in turn where opening fully is
# blocked
RELEASING = 0.15  # of the full opening: fingers opened this much wider let go of what they held
NEAR = 0.02  # [m] margin around the hand's bounding box for objects worth testing
Stop = tuple[float, WorldObject, set[LinkPair]]  # opening, what is squeezed, touching pairs


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


def _probe(robot: ProjectedRobot, arm: str, fraction: float) -> None:
    """Put the gripper ``fraction`` of the way from closed (0) to open (1), to look: the
    closing is probed this way, and the fingers put back before they move."""
    robot.world.set_joint_states(robot.name, gripper_of(robot, arm).at(fraction))


def _move_to(
    robot: ProjectedRobot, arm: str, fraction: float, squeezed: Collection[LinkPair] = ()
) -> dict[str, float]:
    """Move the gripper ``fraction`` of the way from closed (0) to open (1) along a checked
    trajectory (``squeezed`` pairs may touch where the closing stopped; the trajectory
    stores them as the hand's contact, :data:`~robocram.motion.hand_contact.HAND_CONTACT_DEPTH`
    deep, for the audit to hold the squeeze to); return its joints' values.

    Raises:
        GripperPathBlocked: the fingers' way runs into something; they did not move.
    """
    world = robot.world
    goal = {
        j: world.bodies.joint_limits(robot.name, j).clamp(v)
        for j, v in gripper_of(robot, arm).at(fraction).items()
    }
    what = f"{robot.name}'s {arm} gripper"
    bounded = squeezed or _start_contacts(robot, arm)
    try:
        hand = (
            HandContact(frozenset(link for link, _ in bounded), frozenset(o for _, o in bounded))
            if bounded
            else None
        )
        return move_along_checked(
            robot, goal, kind="gripper", what=what, allowed_pairs=bounded, hand=hand
        )
    except ManipulationPathBlocked as blocked:
        master = gripper_of(robot, arm).names[0]
        raise GripperPathBlocked(
            f"{what} cannot move to {goal[master]:.3f}: {blocked}; the fingers did not move",
            gripper=arm,
            goal=goal[master],
            colliding_pairs=blocked.colliding_pairs,
            path_fraction=blocked.path_fraction,
        ) from blocked


def _start_contacts(robot: ProjectedRobot, arm: str) -> set[LinkPair]:
    """The (gripper link, object part) pairs touching where a motion of the fingers
    begins (a hand round a handle it was put on, up to the hand's bound deep): the motion
    keeps them, and its trajectory stores them bounded as the approach's did, so the
    audit holds the fingers to the hand's bound, not to a stranger's 1 mm."""
    links = _squeezing_links(robot, arm)
    found: set[LinkPair] = set()
    for obj in robot.world:
        if obj.name != robot.name:  # the hand's links alone: the whole robot costs ~10x
            found |= _touching(robot, links, obj)
    return found


def _opening(robot: ProjectedRobot, arm: str) -> float:
    """How far open the gripper is now (0 closed, 1 open), within [0, 1]."""
    gripper = gripper_of(robot, arm)
    master = robot.world.joint_states(robot.name)[gripper.names[0]]
    return min(max(gripper.fraction_of(master), 0.0), 1.0)


def open_gripper(robot: ProjectedRobot, arm: str) -> dict[str, float]:
    """Open ``arm``'s gripper fully and release what it holds; return the joint values.

    Raises:
        GripperPathBlocked: the fingers cannot open; they did not move and hold on.
    """
    if gripper_of(robot, arm).is_suction:
        reached: dict[str, float] = {}
    else:
        try:
            reached = _move_to(robot, arm, 1.0)
        except GripperPathBlocked as blocked:
            if not _holding(robot, arm):  # an empty hand opens for a grasp: fully or not
                raise
            reached = _opened_part_way(robot, arm, blocked)
    release(robot, arm)
    return reached


def _opened_part_way(
    robot: ProjectedRobot, arm: str, blocked: GripperPathBlocked
) -> dict[str, float]:
    """Open ``arm``'s fingers, letting go of what they hold, as far as :data:`PART_WAY`
    allows where opening fully is blocked (a wrist flexed far back puts the PR2's fully
    open finger into its own forearm as it lets a bowl's rim go); wider by
    :data:`RELEASING` than now, or ``blocked`` is raised (the fingers did not move)."""
    now = _opening(robot, arm)
    for fraction in PART_WAY:
        if fraction < now + RELEASING:
            break
        try:
            return _move_to(robot, arm, fraction)
        except GripperPathBlocked:
            continue
    raise blocked


def close_gripper(robot: ProjectedRobot, arm: str) -> dict[str, float]:
    """Close ``arm``'s gripper fully, or until its fingers meet what is in their way (a
    handle); nothing is attached.

    Raises:
        GripperPathBlocked: the fingers meet it at once (no closing is free).
    """
    if gripper_of(robot, arm).is_suction:
        return {}  # no finger to move
    try:  # mostly nothing is in the way: one checked motion, no probing
        return _move_to(robot, arm, 0.0)
    except GripperPathBlocked as blocked:
        hit = {other.split("/")[0] for _, other in blocked.colliding_pairs or ()}
        links = _squeezing_links(robot, arm)
        candidates = [
            robot.world.object(name)
            for name in sorted(hit)
            if name in robot.world and name != robot.name
        ]
        before = {obj.name: _touching(robot, links, obj) for obj in candidates}

        def meets(obj: WorldObject) -> bool:  # squeezes it, or touches it where it did not
            return _squeezed(robot, links, obj) or bool(
                _touching(robot, links, obj) - before[obj.name]
            )

        found = _closing_stop(robot, arm, links, candidates, meets)
        if found is None:
            raise
        fraction, _, touching = found
        return _move_to(robot, arm, fraction, touching)


def set_gripper(robot: ProjectedRobot, arm: str, position: float) -> dict[str, float]:
    """Set ``arm``'s gripper so that its master joint is at ``position`` [rad | m].

    Raises:
        GripperGoalNotReached: ``position`` lies beyond the closed or open value (the
            gripper moves to the nearest of them).
        GripperPathBlocked: the fingers' way runs into something; they did not move.
    """
    gripper = gripper_of(robot, arm)
    if gripper.is_suction:
        return {}  # no finger to set
    fraction = gripper.fraction_of(float(position))
    reached = _move_to(robot, arm, min(max(fraction, 0.0), 1.0))
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


def _holding(robot: ProjectedRobot, arm: str) -> list[str]:
    """The objects attached to ``arm``'s hand."""
    links = _arm_links(robot.arm(arm))
    return [o for o, link in robot.world.bodies.attachments(robot.name).items() if link in links]


def release(robot: ProjectedRobot, arm: str) -> list[str]:
    """Detach every object held by ``arm``'s hand; return their names."""
    held = _holding(robot, arm)
    for name in held:
        robot.world.detach(name)
    return held


def _squeezed(
    robot: ProjectedRobot, links: set[str], obj: WorldObject, reach: float = TOUCH
) -> bool:
    """Whether ``links`` touch ``obj`` (come within ``reach`` [m]) from opposing sides."""
    points = robot.world.contacts.links_contact_points(robot.name, links, obj, distance=reach)
    normals = [p.normal_on_b for p in points if p.link_a in links and p.distance <= reach]
    return any(
        sum(a * b for a, b in zip(n, m, strict=True)) < OPPOSED
        for i, n in enumerate(normals)
        for m in normals[i + 1 :]
    )


def _depths(robot: ProjectedRobot, links: set[str], obj: WorldObject) -> dict[str, float]:
    """How deep [m] each of ``links`` is in ``obj`` now (those touching it)."""
    found: dict[str, float] = {}
    for p in robot.world.contacts.links_contact_points(robot.name, links, obj, distance=0.0):
        if p.link_a in links:
            found[p.link_a] = max(found.get(p.link_a, 0.0), -p.distance)
    return found


def _sunk(
    robot: ProjectedRobot, links: set[str], obj: WorldObject, start: dict[str, float]
) -> str | None:
    """The link of ``links`` sunk deeper than :data:`SINK` into ``obj`` since the closing
    began (``start``: the depths then; a jaw that does not move keeps its own), if any: one
    finger met it long before the other (an off-centre grasp, or a curved finger's hull)."""
    now = _depths(robot, links, obj)
    return next((k for k, d in now.items() if d > max(SINK, start.get(k, 0.0) + TOUCH)), None)


def _held_between(
    robot: ProjectedRobot,
    arm: str,
    links: set[str],
    fraction: float,
    obj: WorldObject,
    start: dict[str, float],
) -> None:
    """Check that the closing stopped at ``fraction`` holds ``obj`` between the fingers:
    squeezed, or, where a finger sank to :data:`SINK` first, the other side within the
    hand's bound of it (the object would slide that far into the grip).

    Raises:
        GripperMetOneSide: one finger met ``obj`` and the other side is farther than
            the bound; the fingers did not move.
    """
    states = robot.world.joint_states(robot.name)
    before = {j: states[j] for j in gripper_joints(robot, arm)}
    try:
        _probe(robot, arm, fraction)
        if _squeezed(robot, links, obj, HAND_CONTACT_DEPTH):
            return
        sunk = _sunk(robot, links, obj, start)
        shift = _centring_shift(robot, arm, links, obj, fraction)
    finally:
        robot.world.set_joint_states(robot.name, before)
    raise GripperMetOneSide(
        f"{robot.name}'s {arm} gripper met {obj.name} on one side only: {sunk} is "
        f"{SINK * 1000:.0f} mm in while no finger on the other side is within "
        f"{HAND_CONTACT_DEPTH * 1000:.0f} mm; grasp it centred between the fingers",
        gripper=arm,
        position=gripper_of(robot, arm).at(fraction)[gripper_joints(robot, arm)[0]],
        shift=shift,
        met=obj.name,
    )


def _centring_shift(
    robot: ProjectedRobot, arm: str, links: set[str], obj: WorldObject, fraction: float
) -> tuple[float, float, float] | None:
    """[m, map] how far to move the open hand so the fingers meet ``obj`` together, as
    the gripper stands at ``fraction`` (one side in, the other ``gap`` away): along the
    first side's contact normal (away from the object), by half the misfit when the other
    side closes too, by the gap when it stays (a fixed jaw). None: no other side in sight."""
    points = robot.world.contacts.links_contact_points(
        robot.name, links, obj, distance=CENTRING_REACH
    )
    mine = [p for p in points if p.link_a in links]
    first = min(mine, key=lambda p: p.distance, default=None)
    if first is None:
        return None
    normal = first.normal_on_b
    others = [
        p for p in mine if sum(a * b for a, b in zip(normal, p.normal_on_b, strict=True)) < OPPOSED
    ]
    if not others:
        return None
    other = min(others, key=lambda p: p.distance)
    moving = _moves_when_closing(robot, arm, other.link_a, fraction)
    misfit = other.distance - first.distance  # [m] the gap plus the first side's depth
    travel = misfit / 2 if moving else other.distance
    return (normal[0] * travel, normal[1] * travel, normal[2] * travel)


def _moves_when_closing(robot: ProjectedRobot, arm: str, link: str, fraction: float) -> bool:
    """Whether ``link`` moves as the gripper closes from ``fraction`` (not a fixed jaw)."""
    world = robot.world
    here = world.link_pose(robot.name, link).position
    _probe(robot, arm, max(fraction - 0.1, 0.0))
    there = world.link_pose(robot.name, link).position
    _probe(robot, arm, fraction)
    return _moved(here, there) > 1e-8


def _moved(a: Vector3, b: Vector3) -> float:
    """The squared distance [m^2] between two points."""
    return sum((p - q) ** 2 for p, q in zip(a, b, strict=True))


def _near_hand(robot: ProjectedRobot, links: set[str]) -> list[WorldObject]:
    """Movable objects, not held, whose bounding box comes within :data:`NEAR` of the hand."""
    world = robot.world
    boxes = [world.contacts.link_aabb(robot.name, link) for link in links]
    low = [min(b[0][k] for b in boxes) - NEAR for k in range(3)]
    high = [max(b[1][k] for b in boxes) + NEAR for k in range(3)]
    held = set(world.bodies.attachments(robot.name))
    found = []
    for obj in world.objects():
        if obj.name == robot.name or obj.is_static or obj.name in held:
            continue
        lo, hi = world.aabb(obj)
        if all(lo[k] <= high[k] and hi[k] >= low[k] for k in range(3)):
            found.append(obj)
    return found


def _squeezing_links(robot: ProjectedRobot, arm: str) -> set[str]:
    spec = robot.arm(arm)
    return {
        link for link in (*spec.gripper_links, *spec.hand_links) if link in robot.body.link_index
    }


def grip(robot: ProjectedRobot, arm: str) -> str:
    """Close ``arm``'s gripper until it squeezes an object, attach it and return its name.

    Raises:
        GripperClosedCompletely: the gripper closed without squeezing anything movable
            (fully, or onto what does not move, as :func:`close_gripper` does).
        GripperPathBlocked: the fingers' way runs into something else; they did not move.
    """
    if gripper_of(robot, arm).is_suction:
        return suction_grip(robot, arm)
    links = _squeezing_links(robot, arm)
    near = _near_hand(robot, links)
    depths = {obj.name: _depths(robot, links, obj) for obj in near}
    found = _closing_stop(
        robot, arm, links, near,
        lambda obj: _squeezed(robot, links, obj)
        or _sunk(robot, links, obj, depths[obj.name]) is not None,
    )  # fmt: skip
    if found is None:
        found = _closed_round_thin(robot, arm, links, near)
    if found is None:  # closes as closing does: fully, or onto a handle's bar
        closed = close_gripper(robot, arm)[gripper_joints(robot, arm)[0]]
        raise GripperClosedCompletely(
            f"{robot.name}'s {arm} gripper closed on nothing: no movable object was squeezed "
            "between its fingers",
            gripper=arm,
            position=closed,
        )
    fraction, held, touching = found
    _held_between(robot, arm, links, fraction, held, depths[held.name])
    _move_to(robot, arm, fraction, touching)
    robot.world.attach(held, robot.name, robot.arm(arm).end_effector_link)
    return held.name


def _closed_round_thin(
    robot: ProjectedRobot, arm: str, links: set[str], candidates: list[WorldObject]
) -> Stop | None:
    """Closed fully on a wall thinner than the closed fingers' gap (a bowl's rim, 6 mm,
    in a Boxy's hand, whose fingers stop 6.5 mm apart): the first of ``candidates`` one
    finger touches and the other side comes within the hand's bound of, as
    :func:`_held_between` holds an object the closing stopped on; None if none, or if the
    closed fingers meet (a Panda's, closed beside a mug's handle, held nothing)."""
    states = robot.world.joint_states(robot.name)
    start = {j: states[j] for j in gripper_joints(robot, arm)}
    try:
        opposite = _opposite_fingers(robot, arm, links)
        _probe(robot, arm, 0.0)
        if not opposite or robot.world.contacts.self_contacts(robot.name, opposite, CLOSED_GAP):
            return None  # closed fingers that meet hold nothing thin between them (a Panda's)
        for obj in candidates:
            if _touching(robot, links, obj) and _squeezed(robot, links, obj, HAND_CONTACT_DEPTH):
                return 0.0, obj, _touching(robot, links, obj)
        return None
    finally:
        robot.world.set_joint_states(robot.name, start)


def _opposite_fingers(robot: ProjectedRobot, arm: str, links: set[str]) -> list[LinkPair]:
    """The pairs of ``links`` that both move and move apart as the gripper opens (fingers
    on opposite sides), by more than :data:`CLOSED_GAP`; the gripper is left open."""
    world = robot.world
    _probe(robot, arm, 0.0)
    closed = {link: world.link_pose(robot.name, link).position for link in links}
    _probe(robot, arm, 1.0)
    opened = {link: world.link_pose(robot.name, link).position for link in links}
    names = sorted(link for link in links if math.dist(opened[link], closed[link]) > CLOSED_GAP)
    return [
        (a, b)
        for i, a in enumerate(names)
        for b in names[i + 1 :]
        if math.dist(opened[a], opened[b]) - math.dist(closed[a], closed[b]) > CLOSED_GAP
    ]


def _closing_stop(
    robot: ProjectedRobot,
    arm: str,
    links: set[str],
    candidates: list[WorldObject],
    stops: Callable[[WorldObject], bool],
) -> Stop | None:
    """Where closing first ``stops`` on one of ``candidates``: the opening (0 closed, 1
    open), the object and the pairs touching there; None if nothing stops it up to fully
    closed. Probes only: the gripper is as before after."""
    before = _opening(robot, arm)
    if not candidates:
        return None
    states = robot.world.joint_states(robot.name)
    start = {j: states[j] for j in gripper_joints(robot, arm)}
    try:
        for step in range(1, CLOSING_STEPS + 1):
            checkpoint()  # a stopped task ends the probing here; the fingers go back
            fraction = before * (1 - step / CLOSING_STEPS)
            _probe(robot, arm, fraction)
            held = next((o for o in candidates if stops(o)), None)
            if held is not None:
                outside = before * (1 - (step - 1) / CLOSING_STEPS)
                stop = _first_stop(robot, arm, held, stops, fraction, outside)
                _probe(robot, arm, stop)
                return stop, held, _touching(robot, links, held)
        return None
    finally:
        robot.world.set_joint_states(robot.name, start)


def _first_stop(
    robot: ProjectedRobot,
    arm: str,
    obj: WorldObject,
    stops: Callable[[WorldObject], bool],
    inside: float,
    outside: float,
) -> float:
    """Bisect the opening between ``inside`` (``obj`` stops the fingers) and ``outside``
    (it does not); the former."""
    for _ in range(BISECTION_STEPS):
        checkpoint()
        middle = (inside + outside) / 2
        _probe(robot, arm, middle)
        if stops(obj):
            inside = middle
        else:
            outside = middle
    return inside


def _touching(robot: ProjectedRobot, links: set[str], obj: WorldObject) -> set[LinkPair]:
    """The (gripper link, part of ``obj``) pairs within :data:`TOUCH` as the gripper is
    now: at the squeeze, a finger that met ``obj`` before the other may have sunk in a
    little, so these may touch while the fingers close on it. Named as the motion
    checker names parts: ``object/link`` for an object of several links."""
    several = len(obj.link_index) > 1
    return {
        (p.link_a, f"{obj.name}/{p.link_b}" if several else obj.name)
        for p in robot.world.contacts.links_contact_points(robot.name, links, obj, distance=TOUCH)
        if p.link_a in links and p.distance <= TOUCH
    }
