"""The robot a plan runs on, as the knowledge base knows it: the value plans pass around.

Plans never hold a world (the same plan drives a real robot), so their robot is not the
world's :class:`~robocram.world.robot_handle.RobotHandle` but the robot's entry in the
current knowledge base: :func:`current_robot` makes a :class:`KnownRobot` once per plan
step and the plan hands it down. Each method asks one row of the predicate table
(``robocram.knowledge``) and returns Python values or the row's frozen dataclass, so a
misspelt predicate or a swapped argument is a type error, not an empty answer on one
robot. A fact a plan cannot do without raises :class:`PlanSetupError` naming it. The
knowledge base is read when asked, not kept: a plan prospected in another world asks
that world's.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from robocram.knowledge import grasp_predicates as gp
from robocram.knowledge import robot_predicates as rp
from robocram.knowledge.world_predicates import ATTACHED, JOINT_STATE
from robocram.logic import UnknownPredicateError, current_kb
from robocram.plans.errors import PlanSetupError

NO_GRASP_MODEL = (
    "the knowledge base has no grasp predicates (object_grasp/7); run the plan in an "
    "environment that installs them, such as simulated_robot(world, robot)"
)


def current_robot() -> KnownRobot:
    """The robot of the current knowledge base (its ``robot/1``)."""
    hint = (
        "found no robot/1 in the current knowledge base; run the plan inside an "
        "environment such as simulated_robot(world, 'pr2')"
    )
    try:
        row = rp.ROBOT.first(current_kb())
    except UnknownPredicateError as err:
        raise PlanSetupError(hint) from err
    if row is None:
        raise PlanSetupError(hint)
    return KnownRobot(row.robot)


@dataclass(frozen=True)
class KnownRobot:
    """A robot of the current knowledge base, by its name there (``robot/1``)."""

    name: str

    def __str__(self) -> str:
        return self.name

    def arms(self) -> list[str]:
        """The robot's manipulating arms, in the KB's order."""
        return [row.arm for row in rp.ARM.answers(current_kb(), robot=self.name)]

    def parking(self, arm: str) -> rp.ParkingPose | None:
        """The parking configuration of ``arm``, or None when the KB has none."""
        return rp.ROBOT_ARMS_PARKING_JOINT_STATES.first(current_kb(), robot=self.name, arm=arm)

    def neck_parking(self) -> rp.NeckParkingPose | None:
        """The neck's parking configuration, or None when the KB has none."""
        return rp.ROBOT_NECK_PARKING_JOINT_STATES.first(current_kb(), robot=self.name)

    def torso_limit(self, which: Literal["upper", "lower"]) -> float | None:
        """The ``upper`` or ``lower`` limit [m | rad] of the torso joint; None without a torso."""
        kb = current_kb()
        torso = rp.ROBOT_TORSO_LINK_JOINT.first(kb, robot=self.name)
        if torso is None:
            return None
        limit = rp.JOINT_UPPER_LIMIT if which == "upper" else rp.JOINT_LOWER_LIMIT
        row = limit.first(kb, robot=self.name, joint=torso.joint)
        return None if row is None else row.limit

    def torso_position(self) -> float | None:
        """The torso joint's value [m | rad] now; None without a torso (or a world to ask)."""
        kb = current_kb()
        torso = rp.ROBOT_TORSO_LINK_JOINT.first(kb, robot=self.name)
        if torso is None:
            return None
        try:
            row = JOINT_STATE.first(kb, robot=self.name, joint=torso.joint)
        except UnknownPredicateError:
            return None
        return None if row is None else row.value

    def joint_position(self, joint: str) -> float | None:
        """The value [m | rad] of the robot's ``joint`` now; None without a world to ask."""
        try:
            row = JOINT_STATE.first(current_kb(), robot=self.name, joint=joint)
        except UnknownPredicateError:
            return None
        return None if row is None else row.value

    def has_torso(self) -> bool:
        """Whether the robot has a torso joint."""
        return rp.ROBOT_TORSO_LINK_JOINT.holds(current_kb(), robot=self.name)

    def torso_carried_links(self) -> set[str]:
        """The links the torso joint moves (its child and every link below it); empty
        without a torso. A Boxy's arms hang on its torso, its neck on the base."""
        kb = current_kb()
        torso = rp.ROBOT_TORSO_LINK_JOINT.first(kb, robot=self.name)
        if torso is None:
            return set()
        below: dict[str, list[str]] = {}
        for row in rp.JOINT_PARENT.answers(kb, robot=self.name):
            child = rp.JOINT_CHILD.first(kb, robot=self.name, joint=row.joint)
            if child is not None:
                below.setdefault(row.link, []).append(child.link)
        first = rp.JOINT_CHILD.first(kb, robot=self.name, joint=torso.joint)
        carried, todo = set(), [first.link if first is not None else torso.link]
        while todo:
            link = todo.pop()
            if link not in carried:
                carried.add(link)
                todo += below.get(link, [])
        return carried

    def tool_frame(self, arm: str) -> str:
        """The tool frame of ``arm``."""
        row = rp.ROBOT_TOOL_FRAME.first(current_kb(), robot=self.name, arm=arm)
        if row is None:
            raise PlanSetupError(f"{self.name} has no robot_tool_frame/3 for arm {arm!r}")
        return row.frame

    def end_effector_link(self, arm: str) -> str | None:
        """The link ``arm`` holds objects with, or None when the KB does not say."""
        row = rp.END_EFFECTOR_LINK.first(current_kb(), robot=self.name, arm=arm)
        return None if row is None else row.link

    def held_objects(self, arms: list[str]) -> dict[str, str]:
        """The object each of ``arms``' hands holds now (``attached/4`` on its end
        effector link); arms holding nothing left out."""
        kb = current_kb()
        held = {}
        for arm in arms:
            link = self.end_effector_link(arm)
            row = ATTACHED.first(kb, robot=self.name, link=link) if link is not None else None
            if row is not None:
                held[arm] = row.object
        return held

    def base_frame(self) -> str:
        """The robot's base frame."""
        row = rp.ROBOT_BASE_FRAME.first(current_kb(), robot=self.name)
        if row is None:
            raise PlanSetupError(f"no robot_base_frame/2 for {self.name!r}; load its description")
        return row.frame

    def working_yaw(self, arm: str) -> float:
        """The direction [rad] about the base's z that ``arm`` works in (0: straight ahead)."""
        row = rp.ARM_WORKING_DIRECTION.first(current_kb(), robot=self.name, arm=arm)
        return 0.0 if row is None else row.yaw

    def first_arm_link(self, arm: str) -> str | None:
        """The first link of ``arm`` (its shoulder), or None when the KB lists none."""
        row = rp.ARM_LINKS.first(current_kb(), robot=self.name, arm=arm)
        return row.links[0] if row is not None and row.links else None

    def neck_links(self) -> tuple[str, ...]:
        """The links of the robot's neck (a pan-tilt head's, or a neck arm's); empty if none."""
        row = rp.ROBOT_NECK_LINKS.first(current_kb(), robot=self.name)
        return tuple(row.links) if row is not None else ()

    def grasping_arms(self) -> list[str]:
        """The robot's arms with a gripper (``grasping_arm/2`` of the grasp model)."""
        try:
            return [row.arm for row in gp.GRASPING_ARM.answers(current_kb(), robot=self.name)]
        except UnknownPredicateError as err:
            raise PlanSetupError(NO_GRASP_MODEL) from err

    def limb_links(self) -> set[str]:
        """Every link of the robot's arms, hands and neck: what is not its body."""
        kb = current_kb()
        links = set(self.neck_links())
        for arm in self.arms():
            for predicate in (rp.ARM_LINKS, rp.HAND_LINKS):
                row = predicate.first(kb, robot=self.name, arm=arm)
                links.update(row.links if row is not None else ())
        return links

    def hand_links(self, arm: str) -> set[str]:
        """The wrist of ``arm`` and every link below it (its palm and fingers)."""
        row = rp.HAND_LINKS.first(current_kb(), robot=self.name, arm=arm)
        return set(row.links) if row is not None else set()

    def is_suction(self, arm: str) -> bool:
        """Whether ``arm``'s hand is a suction hand: no gripper joint (it holds what its tool
        frame touches)."""
        return rp.GRIPPER_JOINT.first(current_kb(), robot=self.name, arm=arm) is None

    def gripper_links(self, arm: str) -> set[str]:
        """The links ``arm``'s gripper joints move (its fingers, jaws)."""
        return {row.link for row in rp.GRIPPER_LINK.answers(current_kb(), robot=self.name, arm=arm)}
