"""Where a table and a mug go for a robot, worked out from its description alone.

Nothing is keyed on robot names, so a new robot gets a scene too. The rules:

- the arm is the right-most arm with a gripper (smallest shoulder y);
- the robot stands turned so that the arm's working direction
  (:mod:`robocram.robots.arm_envelope`: straight ahead for most, its base's -y for
  Stretch) points along the map's x, where the table is; everything below is in the map;
- an arm's lift (its leading vertical prismatic joints) counts as a torso: half raised;
- the mug lies ahead of that arm's shoulder; if the arm pans (its first joint turns about
  the vertical), only :data:`SIDE_SHARE` of the shoulder's y out from the robot's
  mid-plane, so it is not hidden under an arm stretched forward; else in the arm's plane;
- the table top sits so that, with the torso half raised, the wrist is
  :data:`WRIST_BELOW_SHOULDER` below the shoulder when the hand grasps the mug from above;
- the mug lies :data:`REACH_SHARE` of the arm's reach (stretched over its joint range: a
  telescope extended) ahead of the shoulder,
  or further if needed for the table's front edge to clear the robot's base footprint
  (its links fixed to the root) by :data:`TABLE_GAP`, the mug :data:`MUG_INSET` behind it;
  but nearer where that share puts the grasping wrist beyond :data:`PAST_RISE_SHARE` of the
  arm's reach from the top of the rise along its first joint's axis
  (:mod:`robocram.robots.arm_rise`: the SO-100's second joint sits 0.10 m above its pan),
  the table's front edge then :data:`NEAR_TABLE_GAP` past the footprint at least;
- with a head that only pans (Baxter's), the mug lies at least as far out as the lower
  edge of the camera's view, panned towards the table;
- with a pan-tilt head, the mug lies at least as far out as the camera's optical axis,
  panned towards the table and tilted down as far as it goes with the torso up, meets
  it: looking aims that axis at the target, and a camera close above a low table cannot
  look that steeply;
- the shoulder must reach the wrist's grasp position; where it cannot, a pan-tilt camera
  (no torso) may look farther out, tilted down to its limit, the mug nearer in the lower
  part of its view (:data:`VIEW_EDGE_SHARE`), the table as high (TALOS); else (a camera
  that cannot look down steeply puts the mug beyond the arm: TIAGo dual), the table
  rises in steps until the wrist is 0.3 m above the shoulder
  (:data:`WRISTS_BELOW_SHOULDER`), the mug then within :data:`RAISED_REACH_SHARE` of the
  reach; where none fits, the same tables seen with the torso down (the look lowers it
  when the head cannot tilt down to the target: Armar6's tilts 46 degrees); else the
  robot is unfit;
- a robot whose fixed camera looks onto its own top (:mod:`robocram.scenes.own_top`)
  gets its mug there, where the optical axis meets it, and no table;
- heights are the map's: a robot lifted onto the floor or a pedestal
  (:mod:`robocram.scenes.standing`) gets its table that much higher.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from robocram.kinematics import forward_kinematics
from robocram.robots import ArmDescription, LoadedDescription
from robocram.robots.arm_envelope import arm_envelope, lift_joints
from robocram.robots.arm_rise import arm_rise
from robocram.robots.looking_means import looking_means
from robocram.robots.model_pose import finite_limits
from robocram.scenes.errors import UnfitRobotError
from robocram.scenes.own_top import seen_on_own_top
from robocram.scenes.standing import root_fixed_links
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.world import World

GRASP_HEIGHT = 0.05  # [m] above the mug's bottom, where a top grasp holds it
WRIST_BELOW_SHOULDER = 0.10  # [m] at the grasp, with the torso half raised
WRISTS_BELOW_SHOULDER = (WRIST_BELOW_SHOULDER, 0.0, -0.1, -0.2, -0.3)  # [m] tried in turn:
# a higher table brings the mug nearer a camera that cannot look down steeply (TALOS, TIAGo)
RAISED_REACH_SHARE = 0.85  # of the reach a raised table's mug may be from the shoulder at
# most: the hand comes from above it, so the arm needs room past the grasp
TABLE_GAP = 0.15  # [m] between the base footprint and the table's front edge
NEAR_TABLE_GAP = 0.05  # [m] the same, where the wrist must come in to be in reach past the
# rise at its shoulder (:data:`PAST_RISE_SHARE`)
MUG_INSET = 0.10  # [m] from the table's front edge to the mug
REACH_SHARE = 0.65  # of the arm's stretched length: the mug's x distance from the shoulder
PAST_RISE_SHARE = 0.9  # of the reach from the top of the rise at the shoulder: the grasping
# wrist's distance from there at most (the corpus's complete arms: 0.88 at most; the SO-100's
# 0.10 m rise over its pan put its wrist at 0.99 of it, its grasps 3-37 mm beyond its wrist)
TABLE_DEPTH = 0.6  # [m] along x
SIDE_SHARE = 0.8  # of the shoulder's y: the mug's y, a little inside the arm's line
PAN_VERTICAL = 0.9  # |z| of a first joint's unit axis above which the arm can pan
PAN_STEPS = 72  # pan values tried to look along the arm's working direction
LOOK_MARGIN = 0.05  # [rad] kept from the tilt's limit when looking down at the mug
VIEW_EDGE_SHARE = 0.5  # of the camera's half field below its axis, down to which a mug
# seen while the camera looks farther out may lie (TALOS: seen at 0.61, not at 0.8)


@dataclass(frozen=True)
class TabletopPlacement:
    """The table's height and the mug's position for one robot standing at the origin."""

    arm: str
    table_height: float  # [m]
    mug_xy: tuple[float, float]  # [m] in map
    on_robot: bool = False  # the mug lies on the robot's own top: no table to add
    look_x: float | None = None  # [m] in map: where to aim the camera, farther out than the
    # mug, which then lies in the lower part of the view (None: at the mug)

    @property
    def table_x(self) -> float:
        """The table centre's x [m] in map."""
        return self.mug_xy[0] - MUG_INSET + TABLE_DEPTH / 2


def _joints_for_torso(desc: LoadedDescription, arm: ArmDescription) -> dict[str, float]:
    """The torso and the arm's lift at the middle of their ranges."""
    names = ((desc.torso_joint,) if desc.torso_joint else ()) + lift_joints(desc.model, arm)
    middles = {}
    for name in names:
        limits = finite_limits(desc.model.joints[name])
        if limits is not None:
            middles[name] = sum(limits) / 2
    return middles


def _first(desc: LoadedDescription, arm: ArmDescription) -> str:
    """The arm's first joint after its lift."""
    lift = lift_joints(desc.model, arm)
    return arm.joints[len(lift)] if len(arm.joints) > len(lift) else arm.joints[-1]


def _shoulder(desc: LoadedDescription, arm: ArmDescription, torso: dict[str, float]) -> Vector3:
    first = desc.model.joints[_first(desc, arm)]
    return forward_kinematics(desc, torso, first.child).position


def _pans(desc: LoadedDescription, arm: ArmDescription, torso: dict[str, float]) -> bool:
    """Whether the arm's first joint turns about the vertical (it can swing sideways)."""
    first = desc.model.joints[_first(desc, arm)]
    frame = forward_kinematics(desc, torso, first.child)
    axis = (Pose(orientation=frame.orientation) * Pose(first.axis)).position
    return abs(axis[2]) > PAN_VERTICAL and first.type != "prismatic"


def placement_arm(desc: LoadedDescription) -> ArmDescription | None:
    """The arm the scene places the mug for: the right-most with a gripper (base y)."""
    arms = [a for a in desc.arms.values() if a.gripper is not None and a.joints]
    if not arms:
        return None
    return min(arms, key=lambda a: (_shoulder(desc, a, _joints_for_torso(desc, a))[1], a.name))


def facing_yaw(desc: LoadedDescription) -> float:
    """The map yaw [rad] to stand the robot at, so its arm works along the map's x."""
    arm = placement_arm(desc)
    if arm is None:
        return 0.0
    return -arm_envelope(desc.model, arm, _joints_for_torso(desc, arm)).working_yaw


def _hand_length(desc: LoadedDescription, arm: ArmDescription) -> float:
    """Wrist-to-tool-frame distance [m]: how far above the grasp the wrist stays."""
    wrist = forward_kinematics(desc, {}, arm.end_effector_link)
    tool = forward_kinematics(desc, {}, arm.tool_frame)
    return math.dist((0.0, 0.0, 0.0), (wrist.inverse() * tool).position)


def _look_down(pose: Pose) -> float:
    """Sine of the angle below the horizon that a camera frame's optical z points at."""
    return -(Pose(orientation=pose.orientation) * Pose((0.0, 0.0, 1.0))).position[2]


def _heading(desc: LoadedDescription, joints: dict[str, float]) -> float:
    """The map-free heading [rad] of the camera's optical axis in the base frame."""
    view = forward_kinematics(desc, joints, desc.cameras[0].frame)
    z = (Pose(orientation=view.orientation) * Pose((0.0, 0.0, 1.0))).position
    return math.atan2(z[1], z[0])


def _pan_to(desc: LoadedDescription, yaw: float, pan: str | None = None) -> float:
    """The pan value [rad] (0 for a robot facing along its arm) that looks along the
    map's x for a robot standing at ``yaw``: the one of a few within limits nearest it.
    ``pan``: the joint (default: the pan-tilt head's)."""
    pt = desc.pan_tilt
    joint = pan if pan is not None else (pt.pan_joint if pt is not None else None)
    limits = finite_limits(desc.model.joints[joint]) if joint is not None else None
    if joint is None or limits is None or yaw == 0.0:
        return 0.0
    values = [limits[0] + (limits[1] - limits[0]) * i / PAN_STEPS for i in range(PAN_STEPS + 1)]

    def off(value: float) -> float:
        heading = _heading(desc, {joint: value}) + yaw
        return abs(math.remainder(heading, 2 * math.pi))

    return min(values, key=off)


def _nearest_in_view(
    desc: LoadedDescription, height: float, yaw: float = 0.0, low: bool = False
) -> float:
    """Nearest x [m] at which the camera sees a point ``height`` [m] high.

    The robot stands at map ``yaw`` [rad]; a pan-tilt camera is panned towards the map's x
    and tilted down as far as its limits allow, with the torso up (where the pick-up plan
    looks from; ``low``: down, where the plan lowers it to when the head cannot tilt down
    to the target), and aims its optical axis there; a head that only pans keeps its tilt
    and sees down to the lower edge of its view. -inf when nothing limits it (no head, or
    a camera an arm turns), inf if it cannot look down.
    """
    pt = desc.pan_tilt
    means = looking_means(desc)
    if pt is None and means is not None and means.kind == "pan" and means.joint is not None:
        return _nearest_in_pan_view(desc, means.joint, height, yaw)
    if pt is None and means is None and desc.cameras and not desc.flying:  # nothing turns it
        return _nearest_in_pan_view(desc, None, height, yaw)
    tilt = finite_limits(desc.model.joints[pt.tilt_joint]) if pt is not None else None
    if pt is None or tilt is None or not desc.cameras:
        return -math.inf
    up = finite_limits(desc.model.joints[desc.torso_joint]) if desc.torso_joint else None
    joints = {
        pt.pan_joint: _pan_to(desc, yaw),
        **({desc.torso_joint: up[0] if low else up[1]} if desc.torso_joint and up else {}),
    }
    frame = desc.cameras[0].frame
    turn = Pose(orientation=quat.from_euler(0.0, 0.0, yaw))
    views = [turn * forward_kinematics(desc, {**joints, pt.tilt_joint: v}, frame) for v in tilt]
    view = max(views, key=_look_down)
    return _seen_from(view, math.asin(min(_look_down(view), 1.0)) - LOOK_MARGIN, height)


def _nearest_in_pan_view(
    desc: LoadedDescription, pan: str | None, height: float, yaw: float
) -> float:
    """:func:`_nearest_in_view` for a head that only pans (or a fixed camera, ``pan``
    None): its tilt stays, so the lower edge of its view (half the vertical field below
    the optical axis) bounds it."""
    camera = desc.cameras[0]
    turn = Pose(orientation=quat.from_euler(0.0, 0.0, yaw))
    joints = {pan: _pan_to(desc, yaw, pan)} if pan is not None else {}
    view = turn * forward_kinematics(desc, joints, camera.frame)
    down = math.asin(max(-1.0, min(_look_down(view), 1.0))) + camera.vertical_fov / 2
    return _seen_from(view, down - LOOK_MARGIN, height)


def _view_note(desc: LoadedDescription) -> str:
    """Why the view bounds the mug, where a head that only pans bounds it; else ''."""
    means = looking_means(desc)
    if desc.pan_tilt is not None or not desc.cameras or (means is not None and means.kind != "pan"):
        return ""
    camera = desc.cameras[0]
    down = math.asin(max(-1.0, min(_look_down(forward_kinematics(desc, {}, camera.frame)), 1.0)))
    lowest = math.degrees(down + camera.vertical_fov / 2)
    how = f"its head only pans ({means.joint})" if means is not None else "its camera is fixed"
    return f"; {how}: its camera sees {lowest:.0f} degrees down at most"


def _seen_from(view: Pose, angle: float, height: float) -> float:
    """Nearest x [m] a camera at ``view`` sees a point ``height`` [m] high at, looking
    down at most ``angle`` [rad]."""
    if angle <= 0.0:
        return math.inf
    x, _, z = view.position
    return x + (z - height) / math.tan(angle) if angle < math.pi / 2 else -math.inf


def _footprint_front(world: World, robot: str, below: float) -> float:
    """Foremost x [m] of the robot's links fixed to its root and reaching below ``below``."""
    desc = world.robot(robot).description
    front = 0.0
    for link in sorted(root_fixed_links(desc) & set(world.link_names(robot))):
        low, high = world.contacts.link_aabb(robot, link)
        if low[0] <= high[0] and low[2] < below:
            front = max(front, high[0])
    return front


def shoulder_in_map(world: World, robot: str, arm: ArmDescription) -> Vector3:
    """The arm's shoulder (torso half raised) in the map, the robot as it stands now."""
    desc = world.robot(robot).description
    local = _shoulder(desc, arm, _joints_for_torso(desc, arm))
    return (world.pose(robot) * Pose(local)).position


def table_height(
    world: World, robot: str, arm: ArmDescription, below: float = WRIST_BELOW_SHOULDER
) -> float:
    """The height [m] of a table top under ``arm``'s hand grasping from above with the
    wrist ``below`` [m] under the shoulder, the robot as it stands now (at most 0: its
    shoulder is too low for any table)."""
    desc = world.robot(robot).description
    wrist_z = shoulder_in_map(world, robot, arm)[2] - below
    return wrist_z - _hand_length(desc, arm) - GRASP_HEIGHT


def tabletop_placement(world: World, robot: str) -> TabletopPlacement:
    """The table and mug placement for ``robot`` (already in ``world``, standing where the
    scene stands it: heights are the map's)."""
    desc = world.robot(robot).description
    arm = placement_arm(desc)
    if arm is None:
        raise UnfitRobotError(
            robot,
            "it has no arm with joints and a gripper to pick the mug with; give an "
            "ArmDescription joints (or a base_link) and gripper_joints (or gripper=...)",
        )
    own = seen_on_own_top(world, robot)
    if own is not None:
        return TabletopPlacement(arm.name, own[2], (own[0], own[1]), on_robot=True)
    shoulder = shoulder_in_map(world, robot, arm)
    height = table_height(world, robot, arm)
    if height <= 0:
        raise UnfitRobotError(
            robot,
            f"the shoulder of its {arm.name!r} arm is {shoulder[2]:.2f} m above the floor, too low "
            f"for a table under its hand (it would stand {height:.2f} m high): stand it "
            "higher (tabletop_scene puts such an arm on a pedestal)",
        )
    reasons = []
    lows = (False, True) if desc.torso_joint and desc.pan_tilt is not None else (False,)
    for low in lows:  # the torso lowered: a head that cannot tilt down far enough (Armar6)
        for below in WRISTS_BELOW_SHOULDER:
            share = 1.0 if below == WRIST_BELOW_SHOULDER else RAISED_REACH_SHARE
            placed, unfit = _placement_at(world, robot, arm, below, share, low)
            if placed is None and below == WRIST_BELOW_SHOULDER and not low:
                placed = _placement_in_view_edge(world, robot, arm)
            if placed is not None:
                return placed
            reasons.append(unfit)
    raise UnfitRobotError(robot, reasons[0])


def _placement_at(
    world: World,
    robot: str,
    arm: ArmDescription,
    below: float,
    share: float = 1.0,
    low: bool = False,
) -> tuple[TabletopPlacement | None, str]:
    """The placement with the grasping wrist ``below`` [m] under the shoulder and the mug
    within ``share`` of the arm's reach, seen with the torso up (``low``: down), or None
    and why it does not fit."""
    desc = world.robot(robot).description
    torso = _joints_for_torso(desc, arm)
    root = world.pose(robot)
    yaw = quat.to_euler(root.orientation)[2]
    shoulder = shoulder_in_map(world, robot, arm)
    wrist_z = shoulder[2] - below
    height = table_height(world, robot, arm, below)
    reach = arm_envelope(desc.model, arm, torso).reach
    seen = _nearest_in_view(desc, height - root.position[2], yaw, low)
    side = SIDE_SHARE if _pans(desc, arm, torso) else 1.0
    wrist = (shoulder[0] + REACH_SHARE * reach, side * shoulder[1], wrist_z)
    in_reach = _past_rise_x(world, robot, arm, wrist)
    gap = TABLE_GAP if in_reach >= wrist[0] else NEAR_TABLE_GAP
    past_base = _footprint_front(world, robot, height) + gap + MUG_INSET
    mug_x = max(past_base, in_reach, seen)
    needed = math.dist(shoulder, (mug_x, shoulder[1], wrist_z))
    if needed > share * reach:
        return None, (
            f"its {arm.name} arm reaches {reach:.2f} m but the mug in front of its base "
            f"and in its camera's view (from x = {seen:.2f} m) is {needed:.2f} m from the "
            f"shoulder (table height {height:.2f} m){_view_note(desc)}"
        )
    return TabletopPlacement(arm.name, height, (mug_x, wrist[1])), ""


def _placement_in_view_edge(
    world: World, robot: str, arm: ArmDescription
) -> TabletopPlacement | None:
    """The table at its usual height (:data:`WRIST_BELOW_SHOULDER`) for a pan-tilt camera
    that cannot aim its optical axis that near: the camera looks farther out, tilted down
    to its limit, and the mug lies nearer, in the lower part of its view
    (:data:`VIEW_EDGE_SHARE` of the half field below the axis), within the arm's reach
    (as the first step's mug at that height); None where that does not fit (or the head
    is not pan-tilt, or a torso moves it).

    A raised table (the next step) puts the hand's wrist above the shoulder for a grasp
    from above: TALOS's arms missed its mug so by 3-6 cm at their joint limits."""
    desc = world.robot(robot).description
    pt = desc.pan_tilt
    if pt is None or not desc.cameras or desc.torso_joint:
        return None
    tilt = finite_limits(desc.model.joints[pt.tilt_joint])
    if tilt is None:
        return None
    torso = _joints_for_torso(desc, arm)
    root = world.pose(robot)
    yaw = quat.to_euler(root.orientation)[2]
    shoulder = shoulder_in_map(world, robot, arm)
    wrist_z = shoulder[2] - WRIST_BELOW_SHOULDER
    height = table_height(world, robot, arm)
    reach = arm_envelope(desc.model, arm, torso).reach
    look_x = _nearest_in_view(desc, height - root.position[2], yaw)
    turn = Pose(orientation=quat.from_euler(0.0, 0.0, yaw))
    joints = {pt.pan_joint: _pan_to(desc, yaw)}
    frame = desc.cameras[0].frame
    views = [turn * forward_kinematics(desc, {**joints, pt.tilt_joint: v}, frame) for v in tilt]
    view = max(views, key=_look_down)
    axis = math.asin(min(_look_down(view), 1.0)) - LOOK_MARGIN
    edge = axis + VIEW_EDGE_SHARE * desc.cameras[0].vertical_fov / 2
    seen = _seen_from(view, min(edge, math.pi / 2 - 1e-6), height - root.position[2])
    side = SIDE_SHARE if _pans(desc, arm, torso) else 1.0
    past_base = _footprint_front(world, robot, height) + TABLE_GAP + MUG_INSET
    mug_x = max(past_base, seen)
    far_edge = mug_x - MUG_INSET + TABLE_DEPTH
    needed = math.dist(shoulder, (mug_x, shoulder[1], wrist_z))
    if not math.isfinite(look_x) or look_x > far_edge or needed > reach:
        return None
    place = TabletopPlacement(arm.name, height, (mug_x, side * shoulder[1]))
    return place if look_x <= mug_x else replace(place, look_x=look_x)


def grasp_in_reach_x(
    world: World, robot: str, arm: ArmDescription, spot: Vector3, beyond: float
) -> float:
    """The x [m, map] of an item's ``spot`` on a table top ``spot[2]`` [m] high, or nearer
    where the wrist grasping it from above lies beyond ``beyond`` of the arm's reach from
    the top of the rise at its shoulder: then as far out as :data:`PAST_RISE_SHARE` of it
    (:func:`_past_rise_x`). A spot aside of the mug, as far out, lies farther from the
    shoulder's axis than the mug."""
    desc = world.robot(robot).description
    wrist_z = spot[2] + _hand_length(desc, arm) + GRASP_HEIGHT
    return _past_rise_x(world, robot, arm, (spot[0], spot[1], wrist_z), beyond)


def _past_rise_x(
    world: World,
    robot: str,
    arm: ArmDescription,
    wrist: Vector3,
    beyond: float = PAST_RISE_SHARE,
) -> float:
    """The x [m, map] of ``wrist``, or nearer where it lies beyond ``beyond`` of the arm's
    reach from the top of the rise along its first joint's axis
    (:mod:`robocram.robots.arm_rise`): then as far out as :data:`PAST_RISE_SHARE` of it
    reaches, the wrist's y and z kept. Where no x fits, as before."""
    desc = world.robot(robot).description
    shape = arm_rise(desc.model, arm, _joints_for_torso(desc, arm))
    turn = Pose(orientation=world.pose(robot).orientation)
    shoulder, rise = shoulder_in_map(world, robot, arm), (turn * Pose(shape.rise)).position
    top = (shoulder[0] + rise[0], shoulder[1] + rise[1], shoulder[2] + rise[2])
    room = PAST_RISE_SHARE * shape.reach
    if math.dist(top, wrist) <= max(beyond * shape.reach, room):
        return wrist[0]
    left = room**2 - (wrist[1] - top[1]) ** 2 - (wrist[2] - top[2]) ** 2
    return top[0] + math.sqrt(left) if left > 0.0 else wrist[0]
