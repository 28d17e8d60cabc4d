"""The motion table: one :class:`MotionType` per motion type robocram knows.

The vocabulary is written once here; ``common_motions.py`` generates the grounding rules
from it, environments their ``matching_process_module/2`` facts and process modules their
dispatch. It needs no physics: a ROS environment uses it as it is. See
``common_motions.py`` for the motions in words.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from robocram.designators.location_designator import LocationDesignator
from robocram.designators.motion_type import (
    Answer,
    Atom,
    Command,
    MotionProperty,
    MotionType,
)
from robocram.designators.object_designator import ObjectDesignator
from robocram.tf import Pose, PoseStamped

SIDES = ("left", "right")  # the arm words of CRAM's two-armed motions

_TARGET = (LocationDesignator, Pose, PoseStamped, tuple, list)
_TARGET_TEXT = "a pose, a PoseStamped or a location designator"
_NUMBER = (int, float)


def _target(key: str) -> MotionProperty:
    return MotionProperty(key, _TARGET, _TARGET_TEXT, target=True)


def _atom(key: str, default: str | None = None) -> MotionProperty:
    return MotionProperty(key, (str,), "an atom (str)", default=default)


def _number(key: str, unit: str, default: str | None = None) -> MotionProperty:
    return MotionProperty(key, _NUMBER, f"a number {unit}", default=default)


def _configuration(key: str) -> MotionProperty:
    return MotionProperty(key, (Mapping, list, tuple), "{joint: value} or [[joint, value], ...]")


_EFFORT = _number("effort", "[N]", default="none")
_MODE = _atom("collision_mode", default="avoid_all")
_TOUCHING = _atom("touching", default="none")  # allow_hand: what the hand acts on
_OBJECT = MotionProperty("object", (ObjectDesignator,), "an object designator")
_DIRECTION = MotionProperty("direction", (tuple, list, PoseStamped, str), "a 3-D vector")


def _gripper_action(type_: str, action: str) -> MotionType:
    command = Command("move_gripper_joint", ("gripper", Atom(action), "effort"), goal=(1,))
    return MotionType(type_, (_atom("gripper"), _EFFORT), (command,), "grippers", Answer.GRIPPER)


def _moving_tcp() -> MotionType:
    both = ("left_target", "right_target")
    mode = ("collision_mode", "touching")
    one = [Command("move_tcp", (Atom(side), f"{side}_target", *mode), (1,), both) for side in SIDES]
    return MotionType(
        "moving-tcp",
        (
            _target("left_target"),
            _target("right_target"),
            _atom("arm"),
            _target("target"),
            _MODE,
            _TOUCHING,
        ),
        (
            Command("move_tcp_both", ("left_target", "right_target", "collision_mode"), (0, 1, 2)),
            *one,
            Command("move_tcp", ("arm", "target", *mode), (1,), both),
        ),
        "arms",
        Answer.GOAL,
    )


def _moving_arm_joints() -> MotionType:
    """Joint goals, checked as ``moving-tcp`` is: ``collision_mode`` (``avoid_all`` unless
    given; ``allow_hand`` lets the hand touch ``touching`` within its bound, as a hand
    that let go low in a drawer retraces the joints it came in by)."""
    both = ("left_configuration", "right_configuration")
    configs = [_configuration(k) for k in (*both, "configuration")]
    mode = ("collision_mode", "touching")
    one = [
        Command("move_joints", (Atom(s), f"{s}_configuration", *mode), (1,), both) for s in SIDES
    ]
    return MotionType(
        "moving-arm-joints",
        (configs[0], configs[1], _atom("arm"), configs[2], _MODE, _TOUCHING),
        (
            Command("move_joints_both", (*both, "collision_mode"), (0, 1)),
            *one,
            Command("move_joints", ("arm", "configuration", *mode), (1,), both),
        ),
        "arms",
        Answer.JOINTS,
    )


def _looking() -> MotionType:
    """Looking at a target, a frame or along a direction; or turning the head's joints to a
    configuration (its parking one, where the neck would be in the way of the base)."""
    return MotionType(
        "looking",
        (_target("target"), _atom("frame"), _DIRECTION, _configuration("configuration")),
        tuple(
            Command("move_head", (Atom(mode), key), goal=(1,))
            for mode, key in (
                ("pose", "target"),
                ("frame", "frame"),
                ("direction", "direction"),
                ("joints", "configuration"),
            )
        ),
        "ptu",
        Answer.GOAL,
    )


_PATH = MotionProperty("path", (list, tuple), "a list of poses (map) of the tool point")
_POINT = MotionProperty(
    "tool_point", (Pose, tuple, list), "the tool point's pose in the tool's frame", default="none"
)
_NEEDED = _number("needed", "[0..1]: the share of the path the arm must reach", default="none")
_CONTACTS = MotionProperty(
    "contacts", (list, tuple), "[[object, depth], ...]: what the tool may touch [m]",
    default="none",
)  # fmt: skip


def _tool_motions() -> tuple[MotionType, ...]:
    """Motions of a held tool along a path (resource ``tools``, docs/tool_actions.md)."""
    path = (_atom("arm"), _PATH, _POINT, _NEEDED)
    return (
        MotionType(
            "moving-tool-path",
            (*path, _atom("tool"), _CONTACTS),
            (
                Command(
                    "move_tool_path", ("arm", "path", "tool", "tool_point", "contacts", "needed")
                ),
            ),
            "tools",
            Answer.GOAL,
        ),
        MotionType(
            "pouring",
            (*path, _atom("source"), _atom("destination"), _number("amount", "[ml]")),
            (
                Command(
                    "pour",
                    ("arm", "path", "source", "tool_point", "destination", "amount", "needed"),
                ),
            ),
            "tools",
            Answer.GOAL,
        ),
        MotionType(
            "cutting",
            (
                *path,
                _atom("tool"),
                _CONTACTS,
                _atom("item"),
                MotionProperty("cuts", (list, tuple), "offsets [m] along the object's axis"),
            ),
            (
                Command(
                    "cut",
                    ("arm", "path", "tool", "tool_point", "contacts", "item", "cuts", "needed"),
                ),
            ),
            "tools",
            Answer.GOAL,
        ),
    )


def _table() -> tuple[MotionType, ...]:
    return (
        MotionType(
            "going",
            (_target("target"),),
            (Command("move_base", ("target",)),),
            "navigation",
            Answer.GOAL,
        ),
        MotionType(
            "moving-torso",
            (_number("joint_angle", "[m | rad]"),),
            (Command("move_torso", ("joint_angle",)),),
            "torso",
            Answer.GOAL,
        ),
        _looking(),
        MotionType(
            "detecting",
            (_OBJECT,),
            (Command("detect", ("object",)),),
            "perception",
            Answer.PERCEIVED,
        ),
        MotionType(
            "inspecting",
            (_OBJECT,),
            (Command("inspect", ("object",)),),
            "perception",
            Answer.PERCEIVED,
        ),
        _gripper_action("opening", "open"),
        _gripper_action("closing", "close"),
        _gripper_action("gripping", "grip"),
        MotionType(
            "moving-gripper-joint",
            (_atom("gripper"), _number("joint_angle", "[m | rad]"), _EFFORT),
            (Command("move_gripper_joint", ("gripper", "joint_angle", "effort"), goal=(1,)),),
            "grippers",
            Answer.GRIPPER,
        ),
        _moving_tcp(),
        _moving_arm_joints(),
        MotionType(
            "moving-articulation",
            (
                *(_atom(k) for k in ("arm", "part", "joint", "handle")),
                _number("joint_angle", "[m | rad]"),
            ),
            (Command("move_part", ("arm", "part", "joint", "handle", "joint_angle"), goal=(4,)),),
            "arms",
            Answer.GOAL,
        ),
        *_tool_motions(),
        MotionType(
            "flying",
            (_target("target"),),
            (Command("fly", ("target",)),),
            "flying",
            Answer.GOAL,
            family="flying",
        ),
        MotionType(
            "crouching",
            (_number("depth", "[m] below standing; 0: stand up"),),
            (Command("crouch", ("depth",)),),
            "legs",
            Answer.GOAL,
            family="legged",
        ),
        MotionType(
            "distance-sensing",
            (_DIRECTION,),
            (Command("sense_distance", ("direction",)),),
            "distance_sensor",
            Answer.NO_RANGE,
            family="flying",
        ),
    )


MOTION_TYPES: Mapping[str, MotionType] = MappingProxyType({m.type: m for m in _table()})


def motion_types(family: str | None = None) -> tuple[MotionType, ...]:
    """The motion types of ``family`` (all of them for None), in table order."""
    return tuple(m for m in MOTION_TYPES.values() if family is None or m.family == family)
