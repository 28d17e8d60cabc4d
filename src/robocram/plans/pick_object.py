"""Pick up any detected object: open, pre-grasp, grasp, grip, lift, with any robot.

The grasps come from the knowledge base (``object_grasp/7``, installed by the projection
from the grasp model, docs/grasping.md), best first for each arm; arms are tried nearest
first. A try that fails (the pose is out of reach, the grip closes on nothing) moves on to
the next grasp, then the next arm; when all fail, :class:`PickUpFailed` carries every
cause.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from robocram.designators import ObjectDesignator, a
from robocram.execution import perform
from robocram.execution.failures import (
    GripperLowLevelFailure,
    ManipulationLowLevelFailure,
    ManipulationPoseUnreachable,
)
from robocram.logic import Term, UnknownPredicateError, current_kb
from robocram.plans.errors import PlanSetupError
from robocram.plans.grasp_failures import ObjectUngraspable, PickUpFailed, PickUpUnreachable
from robocram.plans.robot_facts import current_robot
from robocram.tf import Pose, PoseStamped, TfError, transform_pose

GRASPING = {"collision_mode": "allow_hand"}  # the fingers may touch what they close on
NO_DOOR = (
    "the knowledge base has no grasp predicates (object_grasp/7); run the plan in an "
    "environment that installs them, such as simulated_robot(world, robot)"
)
TRIES = (ManipulationLowLevelFailure, GripperLowLevelFailure)  # a try ends, the next starts


@dataclass(frozen=True)
class Held:
    """An object held by an arm: the grasp used and the tool poses (``map``) it took."""

    arm: str
    grasp: str
    object_name: str
    tool_frame: str
    grasp_pose: PoseStamped
    lifted: PoseStamped
    object_in_tool: Pose  # the object's pose in the tool frame while held


def object_spec(obj: ObjectDesignator | str) -> tuple[str, Any, Pose | None]:
    """The object's name, how the grasp predicates name it, and its pose in ``map``.

    A perceived designator with a type and a pose is ``object(Name, Type, Pose)``, so the
    grasps come from its type where no world knows it; a name is looked up in the world.
    """
    name = object_name(obj)
    if isinstance(obj, ObjectDesignator) and obj.get("pose") is not None and obj.get("type"):
        pose = transform_pose(obj.get("pose"), "map")
        return name, Term("object", (name, str(obj.get("type")), pose)), pose.pose
    try:
        return name, name, transform_pose(PoseStamped(name), "map").pose
    except TfError:
        return name, name, None


def object_name(obj: ObjectDesignator | str) -> str:
    """The world name of a perceived object designator (or a name itself)."""
    if isinstance(obj, str):
        return obj
    name = obj.get("name")
    if name is None:
        raise PlanSetupError(
            f"{obj.description} has no name: detect it first (a perceived object designator)"
        )
    return str(name)


def tool_frame(robot: str, arm: str) -> str:
    """The tool frame of ``arm``."""
    answer = current_kb().first("robot_tool_frame(R, A, T)", R=robot, A=arm)
    if answer is None:
        raise PlanSetupError(f"{robot} has no robot_tool_frame/3 for arm {arm!r}")
    return str(answer["T"])


def arms_nearest_first(robot: str, target: Pose | None, arm: str | None) -> list[str]:
    """``[arm]``, or the robot's arms with a gripper, their tool frames nearest first."""
    if arm is not None:
        return [arm]
    try:
        arms = [str(x["A"]) for x in current_kb().query("grasping_arm(R, A)", R=robot)]
    except UnknownPredicateError as err:
        raise PlanSetupError(NO_DOOR) from err
    if not arms:
        raise PlanSetupError(f"{robot} has no arm with a gripper (grasping_arm/2)")
    if target is None:
        return arms

    def distance(choice: str) -> float:
        tool = transform_pose(PoseStamped(tool_frame(robot, choice)), "map").pose
        return tool.distance_to(target)

    return sorted(arms, key=distance)


def grasp_choices(robot: str, spec: Any, arm: str, grasp: str | None) -> list[dict[str, Any]]:
    """The KB's grasps of ``name`` by ``arm`` (only ``grasp`` if given), best first.

    Raises:
        ObjectUngraspable: the hand is too narrow for every grasp of the object.
    """
    kb = current_kb()
    query = "object_grasp(O, R, A, N, G, P, L)"
    name = str(spec.args[0]) if isinstance(spec, Term) else str(spec)
    bindings: dict[str, Any] = {"O": spec, "R": robot, "A": arm}
    if grasp is not None:
        bindings["N"] = grasp
    found = [{"N": grasp, **answer} for answer in kb.query(query, **bindings)]
    if not found:
        refusal = kb.first("object_ungraspable(O, R, A, H, W)", O=spec, R=robot, A=arm)
        if refusal is not None:
            raise ObjectUngraspable(
                f"no grasp of {name!r} fits the {arm} hand of {robot}: it opens "
                f"{refusal['H']:.3f} m, the narrowest grasp needs {refusal['W']:.3f} m",
                object_name=name,
                arm=arm,
                hand_width=float(refusal["H"]),
                needed_width=float(refusal["W"]),
            )
    return found


def _move(arm: str, pose: PoseStamped, **mode: str) -> None:
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=pose), **mode))


def _try_grasp(
    robot: str, name: str, arm: str, choice: dict[str, Any], object_in_map: Pose | None
) -> Held:
    perform(a.motion(type="opening", gripper=arm))
    _move(arm, choice["P"])
    _move(arm, choice["G"], **GRASPING)
    gripped = perform(a.motion(type="gripping", gripper=arm))
    if isinstance(gripped, str) and gripped != name:  # projection names what it holds
        perform(a.motion(type="opening", gripper=arm))
        raise PickUpFailed(f"the {arm} hand gripped {gripped!r}, not {name!r}", object_name=name)
    _move(arm, choice["L"], **GRASPING)
    frame = tool_frame(robot, arm)
    if object_in_map is None:
        object_in_map = transform_pose(PoseStamped(name), "map").pose
    held = choice["G"].pose.inverse() * object_in_map  # as gripped: the grasp keeps it
    return Held(arm, str(choice["N"]), name, frame, choice["G"], choice["L"], held)


def pick_up_object(
    object: ObjectDesignator | str,  # noqa: A002 - CRAM's key
    arm: str | None = None,
    grasp: str | None = None,
) -> Held:
    """Pick up the (detected) object with ``arm`` and ``grasp``, or the first that works.

    Raises:
        ObjectUngraspable: the only arm asked for is too narrow for every grasp.
        PickUpFailed: no arm and grasp picked it up; ``causes`` holds each try's failure.
            :class:`PickUpUnreachable` (also a ``ManipulationPoseUnreachable``) when every
            try was out of reach.
    """
    robot = current_robot()
    name, spec, pose = object_spec(object)
    causes: list[Exception] = []
    arms = arms_nearest_first(robot, pose, arm)
    for choice_arm in arms:
        try:
            choices = grasp_choices(robot, spec, choice_arm, grasp)
        except ObjectUngraspable as failure:
            if arm is not None:
                raise
            causes.append(failure)
            continue
        for choice in choices:
            try:
                return _try_grasp(robot, name, choice_arm, choice, pose)
            except TRIES as failure:
                causes.append(failure)
            except PickUpFailed as failure:
                causes.append(failure)
    unreachable = bool(causes) and all(isinstance(c, ManipulationPoseUnreachable) for c in causes)
    raise (PickUpUnreachable if unreachable else PickUpFailed)(
        f"no arm of {arms} picked up {name!r}"
        + (f" with grasp {grasp!r}" if grasp else "")
        + f" in {len(causes)} tries (causes: "
        + ", ".join(sorted({type(c).__name__ for c in causes}))
        + ")",
        object_name=name,
        causes=causes,
    )
