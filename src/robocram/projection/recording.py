"""A non-physics environment: the same PERFORM calls, only logged.

``recorded_robot("pr2", objects={...})`` grounds motions exactly as the projection does
(common motions, flying motions, the robot's description facts) but its process modules
only append ``(module, command)`` to a log and answer with plausible values, as the
motion table's ``answer`` of each motion type says:

- going, flying, moving-tcp, looking: the target they were given
- moving-torso, crouching: the value asked; opening/closing/gripping: the gripper action (``grip``
  answers the name of the object detected last, or None)
- moving-arm-joints: the configuration, which also moves the robot's joints in the
  recorded kinematic state, so ``transform_pose`` in plans sees the arms where they went
- detecting, inspecting: a designator equated with the one asked for, carrying the pose given in
  ``objects`` for its type or name (in the robot's base frame); none known ->
  ``PerceptionObjectNotFound``
- distance-sensing: ``inf`` (there is no world to measure)

It shows the environment switch: a plan that ran on the projected robot runs here too.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass

from robocram.designators import MOTION_TYPES, Answer, Command, ObjectDesignator
from robocram.execution import (
    Environment,
    MotionProcessModule,
    TaskTree,
    TopLevel,
    matching_facts,
    module_atom,
    top_level,
)
from robocram.execution.failures import PerceptionObjectNotFound
from robocram.grasping import install_grasp_predicates
from robocram.kinematics import forward_kinematics
from robocram.logic import KnowledgeBase, Term
from robocram.projection.arm import joint_values
from robocram.projection.errors import ProjectionError
from robocram.projection.perception import PerceivedObject
from robocram.projection.robot_environment import install_motions, with_legs
from robocram.projection.world_frames import LiveTransformTree
from robocram.robots import (
    LoadedDescription,
    RobotDescription,
    install_description,
    load_description,
)
from robocram.robots.looking_means import with_looking
from robocram.tf import Pose, PoseStamped, using_transform_tree

LogEntry = tuple[str, Term]
PREFIX = "recorded"  # module atoms: recorded_arms, recorded_perception, ...


class RecordedState:
    """The recorded robot: its joint values, the log and what it last detected."""

    def __init__(self, description: LoadedDescription, objects: Mapping[str, PoseStamped]):
        self.description = description
        self.objects = dict(objects)
        self.joints: dict[str, float] = {}
        self.log: list[LogEntry] = []
        self.last_detected: str | None = None
        self._lock = threading.Lock()

    def record(self, module: str, command: Term) -> None:
        """Append one executed command to the log."""
        with self._lock:
            self.log.append((module, command))

    def frame_poses(self) -> Mapping[str, Pose]:
        """Every link's pose in ``map`` by FK of the recorded joints (the base at the origin)."""
        model = self.description.model
        with self._lock:
            joints = dict(self.joints)
        return {link: forward_kinematics(self.description, joints, link) for link in model.links}


class RecordingPM(MotionProcessModule):
    """Logs the table commands of one resource and answers as the table's ``answer`` says."""

    def __init__(self, resource: str, state: RecordedState) -> None:
        self.name = module_atom(PREFIX, resource)  # type: ignore[misc]  # one class, all resources
        self.resource = resource
        super().__init__()
        self.state = state

    def run_command(self, spec: Command, command: Term) -> object:
        """Log ``command`` and return what a real module would plausibly answer."""
        self.state.record(self.name, command)
        return _ANSWERS[_ANSWER_OF[spec]](self.state, spec, command.args)


def _goal(state: RecordedState, spec: Command, args: tuple[object, ...]) -> object:
    goals = tuple(args[i] for i in spec.goal)
    return goals[0] if len(goals) == 1 else goals


def _joints(state: RecordedState, spec: Command, args: tuple[object, ...]) -> dict[str, float]:
    values = joint_values(args[1])
    state.joints.update(values)
    return values


def _gripper(state: RecordedState, spec: Command, args: tuple[object, ...]) -> object:
    return state.last_detected if args[1] == "grip" else args[1]


def _perceived(state: RecordedState, spec: Command, args: tuple[object, ...]) -> object:
    asked = args[0]
    if not isinstance(asked, ObjectDesignator):
        raise ProjectionError(f"perceiving needs an object designator, got {asked!r}")
    return _detect(state, asked)


def _no_range(state: RecordedState, spec: Command, args: tuple[object, ...]) -> float:
    return math.inf


_ANSWERS: dict[Answer, Callable[[RecordedState, Command, tuple[object, ...]], object]] = {
    Answer.GOAL: _goal,
    Answer.JOINTS: _joints,
    Answer.GRIPPER: _gripper,
    Answer.PERCEIVED: _perceived,
    Answer.NO_RANGE: _no_range,
}

_ANSWER_OF = {c: m.answer for m in MOTION_TYPES.values() for c in m.commands}


def _detect(state: RecordedState, asked: ObjectDesignator) -> ObjectDesignator:
    key = next((str(asked.get(k)) for k in ("name", "type") if asked.get(k) in state.objects), None)
    if key is None:
        raise PerceptionObjectNotFound(
            f"the recording robot knows no object fitting {asked.description}; known: "
            f"{sorted(state.objects)} (pass them as objects=...)",
            object_designator=asked,
        )
    pose = state.objects[key]
    kind = str(asked.get("type") or key)
    name = str(asked.get("name") or f"{kind}-1")
    state.last_detected = name
    return asked.make_effective(PerceivedObject(name, kind, pose), type=kind, name=name, pose=pose)


@dataclass(frozen=True)
class RecordingRun:
    """What a ``recorded_robot`` block yields: the log, the environment and the top level."""

    environment: Environment
    top_level: TopLevel
    state: RecordedState

    @property
    def log(self) -> list[LogEntry]:
        """``(module, command)`` in the order executed."""
        return list(self.state.log)

    @property
    def tree(self) -> TaskTree:
        """The task tree of the block."""
        return self.top_level.tree


def recording_environment(
    robot: str | RobotDescription, objects: Mapping[str, PoseStamped] | None = None
) -> tuple[Environment, RecordedState]:
    """An environment of logging modules for ``robot``, and the state they record into."""
    desc = load_description(robot)
    state = RecordedState(desc, objects or {})
    kb = KnowledgeBase()
    install_description(kb, desc)
    install_motions(kb, desc)
    install_grasp_predicates(kb, description=desc)  # objects by type and pose
    resources = with_legs(desc, with_looking(desc, desc.resources()))
    modules = [RecordingPM(resource, state) for resource in resources]
    facts = matching_facts(PREFIX, resources)
    env = Environment(f"recording_{desc.name}", modules, facts=facts, kb=kb)
    return env, state


@contextmanager
def recorded_robot(
    robot: str | RobotDescription,
    objects: Mapping[str, PoseStamped] | None = None,
    name: str = "recorded-robot",
) -> Iterator[RecordingRun]:
    """Run the block as a top level on a robot that only logs its commands."""
    env, state = recording_environment(robot, objects)
    runner = top_level(name=name)
    with using_transform_tree(LiveTransformTree(state)), env, runner:
        yield RecordingRun(env, runner, state)
