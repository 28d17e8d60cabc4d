"""Looking with a camera the arm carries (a wrist camera, no neck): a viewing pose by IK.

The camera frame is put, by IK on the arm's chain with the camera as its tip, at a place
from which its optical axis (z) meets the target with the image upright. The places are
tried in order: where the camera is now (the arm only turns it), then on a ring over the
target on the side of the arm's base, at a few distances and elevations (a step back
and up, so the hand does not hide what it looks at); at each, the image upright first,
then turned about the optical axis (where the arm's limits want it). Each IK solution is
collision-checked as an arm motion avoiding everything, and the arm moves there along a
checked, timed trajectory (planned round obstacles); a pose from which the robot's own
links hide the target (rays from the camera) is taken only if no other is found. An arm
too short of joints to hold a whole camera pose (the SO-101's five) is aimed joint by
joint instead, as a head is (``joint_aim.py``), the camera staying where its joints take
it (where every look failed, aimed again from the arm at rest). IK is counted and
seeded: the same look gives the same joints on any machine.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.execution import checkpoint
from robocram.execution.failures import ManipulationPathBlocked, PtuGoalUnreachable
from robocram.kinematics import IKOptions, IKResult, solve_ik
from robocram.motion.tool_goal import IK_RANDOM_SEED
from robocram.projection.collision_mode import collision_check, putting_back_once
from robocram.projection.joint_aim import aimed_joints
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.look_failures import look_blocked
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import link_pose
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.tf.optical_look_at import optical_look_at
from robocram.world import catalogue_names

VIEW_DISTANCES = (0.45, 0.35, 0.6)  # [m] from the camera to the target on the ring
VIEW_ELEVATIONS = (math.radians(55.0), math.radians(35.0), math.radians(75.0))
VIEW_ROLLS = (0.0, math.pi, math.pi / 2, -math.pi / 2)  # [rad] about the optical axis:
# upright first; a turned image sees the target as well, where the arm's limits want it
VIEW_RESTARTS = 20  # IK descents after the first per viewing place
MIN_DISTANCE = 0.05  # [m] a camera this close to its target cannot look at it
RAISE_MIN = 0.05  # [m] a camera this much under its maximal height may be raised to it
AIM_TOLERANCE = math.radians(1.0)  # [rad] an arm aimed joint by joint ends this near
TURNING = ("revolute", "continuous")
OCCLUDED = 0.1  # [m] a ray stopped farther than this from its end met what hides the target
SIGHT_NEAR = 0.05  # [m] rays start this far out of the camera (as the world's do)
SIGHT_OFFSETS = tuple(
    (dx, dy, dz) for dx in (-0.03, 0.03) for dy in (-0.03, 0.03) for dz in (0.0, 0.06)
)  # [m] round the target: a mug's size


def _ring(robot: ProjectedRobot, arm: str, target: np.ndarray) -> list[np.ndarray]:
    """Viewing places over ``target`` on the side of ``arm``'s base, nearest first."""
    base_link = robot.arm(arm).base_link or robot.description.base_frame
    shoulder = np.asarray(robot.world.link_pose(robot.name, base_link).position, float)
    toward = shoulder - target
    toward[2] = 0.0
    if np.linalg.norm(toward) < 1e-6:
        toward = np.asarray(robot.base_pose().matrix()[:3, 0], float) * -1.0
        toward[2] = 0.0
    toward /= np.linalg.norm(toward)
    up = np.array((0.0, 0.0, 1.0))
    return [
        target + d * (math.cos(e) * toward + math.sin(e) * up)
        for e in VIEW_ELEVATIONS
        for d in VIEW_DISTANCES
    ]


def _places(robot: ProjectedRobot, arm: str, target: np.ndarray) -> list[np.ndarray]:
    frame = robot.description.cameras[0].frame
    now = np.asarray(robot.world.link_pose(robot.name, frame).position, float)
    places = [now, *_ring(robot, arm, target), *_raised(robot, now)]
    return [p for p in places if float(np.linalg.norm(target - p)) > MIN_DISTANCE]


def _raised(robot: ProjectedRobot, now: np.ndarray) -> list[np.ndarray]:
    """The camera straight up from where it is, at the description's maximal height: where
    a stand's check looked from (``costmaps/camera_aim.aimed_cameras``), a target too far
    for the ring (a Panda's wrist camera, parked under a counter's top 1.5 m away)."""
    top = robot.description.cameras[0].maximal_height
    if top is None:
        return []
    high = robot.base_pose().position[2] + top
    return [np.array((now[0], now[1], high))] if high > now[2] + RAISE_MIN else []


def _solve_view(
    robot: ProjectedRobot, arm: str, place: np.ndarray, target: np.ndarray, roll: float
) -> IKResult:
    frame = robot.description.cameras[0].frame
    eye = (float(place[0]), float(place[1]), float(place[2]))
    aim = (float(target[0]), float(target[1]), float(target[2]))
    view = Pose(eye, optical_look_at(eye, aim)) * Pose(orientation=quat.from_euler(0, 0, roll))
    target_in_base = robot.base_pose().inverse() * view
    check = collision_check(robot, arm, "avoid_all")
    options = IKOptions(frame=frame, max_restarts=VIEW_RESTARTS, random_seed=IK_RANDOM_SEED)
    seed = robot.world.joint_states(robot.name)
    with robot.ik_lock, putting_back_once(check):
        return solve_ik(
            robot.description, arm, target_in_base, seed=seed, options=options,
            collision_check=check, stop_check=checkpoint,
        )  # fmt: skip


def look_by_arm(robot: ProjectedRobot, arm: str, target_in_map: Vector3) -> dict[str, float]:
    """Move ``arm`` so the camera it carries looks at ``target_in_map``; the joints set.

    Raises:
        PtuPathBlocked: every viewing pose IK found is blocked on the way; the arm did not move.
        PtuGoalUnreachable: no viewing place has a collision-free IK solution.
    """
    target = np.asarray(target_in_map, float)
    blocked: list[ManipulationPathBlocked] = []
    places = _places(robot, arm, target)
    hidden: list[dict[str, float]] = []  # solutions the robot's own links hide it from
    for place, roll in ((p, r) for p in places for r in VIEW_ROLLS):
        result = _solve_view(robot, arm, place, target, roll)
        if not result.success:
            continue
        goal = dict(result.joint_positions)
        if _sight_blocked(robot, goal, target):
            hidden.append(goal)
            continue
        try:
            return _turn_arm(robot, arm, goal)
        except ManipulationPathBlocked as failure:  # another viewing place may be free
            blocked.append(failure)
    aimed = _aimed_goal(robot, arm, target)  # the joints aimed one by one: a clear view of
    if aimed is not None:  # it before the hidden ones (detecting then says what hides)
        hidden.insert(len(hidden) if _sight_blocked(robot, aimed, target) else 0, aimed)
    for goal in hidden:
        try:
            return _turn_arm(robot, arm, goal)
        except ManipulationPathBlocked as failure:
            blocked.append(failure)
    rested = _aimed_from_rest(robot, arm, target)  # only once all else failed
    if rested is not None and rested not in hidden:
        try:
            return _turn_arm(robot, arm, rested)
        except ManipulationPathBlocked as failure:
            blocked.append(failure)
    if blocked:
        raise look_blocked(robot, target_in_map, blocked[0], f"{arm} arm") from blocked[0]
    frame = robot.description.cameras[0].frame
    raise PtuGoalUnreachable(
        f"{robot.name}'s {arm} arm cannot point its camera {frame} at {tuple(target_in_map)} "
        f"from any of {len(places)} viewing places without a collision; move the base closer",
        target=tuple(target_in_map),
    )


def _turn_arm(robot: ProjectedRobot, arm: str, goal: dict[str, float]) -> dict[str, float]:
    return move_along_checked(
        robot, goal, kind="arm", what=f"{robot.name}'s {arm} arm (looking)", plan=True
    )


def _sight_blocked(robot: ProjectedRobot, goal: dict[str, float], target: np.ndarray) -> bool:
    """Whether, with the joints at ``goal``, a ray from the camera to a point round the
    target meets the robot itself (its hand before a wrist camera: detecting wants nine
    tenths of an object in sight), or anything else short of the target by more than
    :data:`OCCLUDED` (a counter's top before a camera held under it). A household item
    does not count: it may be what the look is for (the Donbot's wrist camera met the mug
    it looked for 9 cm before the table's point behind it, from every view), and one that
    hides another is named by detecting. The world is as before after."""
    world = robot.world
    before = {j: v for j, v in world.joint_states(robot.name).items() if j in goal}
    world.set_joint_states(robot.name, goal)
    try:
        eye = np.asarray(world.link_pose(robot.name, robot.description.cameras[0].frame).position)
        ends = [target + np.asarray(offset) for offset in SIGHT_OFFSETS]
        starts = [eye + SIGHT_NEAR * (end - eye) / np.linalg.norm(end - eye) for end in ends]
        hits = world.view.ray_cast_batch([_point(p) for p in starts], [_point(p) for p in ends])
    finally:
        world.set_joint_states(robot.name, before)
    items = set(catalogue_names())
    return any(
        hit is not None
        and (
            hit.obj.name == robot.name
            or (hit.obj.type not in items and math.dist(hit.position, _point(end)) > OCCLUDED)
        )
        for hit, end in zip(hits, ends, strict=True)
    )


def _point(vector: np.ndarray) -> tuple[float, float, float]:
    return (float(vector[0]), float(vector[1]), float(vector[2]))


def _aimed_goal(robot: ProjectedRobot, arm: str, target: np.ndarray) -> dict[str, float] | None:
    """The arm's joints aimed one by one at the target, when the optical axis then ends
    within :data:`AIM_TOLERANCE` of it; else None. Nothing moves."""
    desc, world = robot.description, robot.world
    model = desc.model
    chain = model.chain(model.root_link, desc.cameras[0].frame)
    turning = {j for j in robot.arm(arm).joints if model.joints[j].type in TURNING}
    axes = [(j.name, j.child) for j in chain if j.name in turning]
    if not axes:
        return None
    wanted = aimed_joints(robot, axes, target)
    goal = {j: world.bodies.joint_limits(robot.name, j).clamp(v) for j, v in wanted.items()}
    return None if _off_axis(robot, goal, target) > AIM_TOLERANCE else goal


def _aimed_from_rest(
    robot: ProjectedRobot, arm: str, target: np.ndarray
) -> dict[str, float] | None:
    """:func:`_aimed_goal` with the arm's joints first at rest (0, within limits), or None:
    aimed one by one, the joints keep what they start from, and the SO-100's, aimed from
    its parked pose at its workcell's bowl 38 degrees aside, folded its forearm into its
    base, while from rest it saw the whole bowl. Asked only after every other look failed;
    the arm is where it was after."""
    world = robot.world
    joints = [j for j in robot.arm(arm).joints if j in world.joint_states(robot.name)]
    before = {j: world.joint_states(robot.name)[j] for j in joints}
    rest = {j: world.bodies.joint_limits(robot.name, j).clamp(0.0) for j in joints}
    if rest == before:
        return None  # already tried from there
    world.set_joint_states(robot.name, rest)
    try:
        goal = _aimed_goal(robot, arm, target)
    finally:
        world.set_joint_states(robot.name, before)
    return goal


def _off_axis(robot: ProjectedRobot, goal: dict[str, float], target: np.ndarray) -> float:
    """[rad] between the optical axis and the target with the joints at ``goal``, placed
    by the kinematic model from the robot's base pose in the world."""
    desc, world = robot.description, robot.world
    state = {**world.joint_states(robot.name), **goal}
    camera = world.pose(robot.name) * link_pose(desc.model, desc.cameras[0].frame, state)
    view = camera.matrix()
    to_target = target - view[:3, 3]
    cosine = float(view[:3, 2] @ to_target / np.linalg.norm(to_target))
    return math.acos(max(-1.0, min(1.0, cosine)))
