"""An IK query that cannot succeed, told from its first solution refused for the hand.

Every solution IK accepts puts the tool within the query's tolerances of the target, so
the links no joint of the query moves relative to the tool (the hand below the arm's last
joint: the gripper's joints are held) stand nearly where they stood at any other: a point
``r`` from the tool frame lies at most ``position_tolerance + r * orientation_tolerance``
from where it would be at the target, twice that from where it is at another solution. A
hand link deeper in what it may not touch than that (in what it acts on: deeper than its
bound by that) at one refused solution is in it at every solution: the query fails.

Only a query whose failure is not read may stop there (:class:`CertainMiss`): the
torso-held try before the torso-free one, whose own failure says why. It then gives the
same answers, later queries being seeded per query, without its hundred refused checks.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.motion.hand_contact import HandContact, contact_depth
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import RobotModel

MISS_MARGIN = 0.002  # [m] beyond the tolerances' bound: the contact queries' own numerics
LinkPair = tuple[str, str]  # (robot link, object or object/link)


class CertainMiss(ManipulationPoseUnreachable):
    """An IK query stopped: a hand link is too deep in something for any solution.

    Raised by a :class:`CertainMissJudge` from inside the query's collision check, and
    caught by the caller that installed the judge, which reads nothing of the query but
    its failure. ``colliding_pairs`` holds the one pair; ``depth`` [m] how deep it is at
    the refused solution, ``bound`` [m] the depth that makes it certain.
    """

    depth: float | None = None
    bound: float | None = None
    summary = "an IK query was stopped: no solution of it can be free of this contact"


@dataclass(frozen=True)
class CertainMissJudge:
    """Called with a candidate's refused world pairs while the robot stands at it; raises
    :class:`CertainMiss` when one is certain at every solution of the query."""

    robot: ProjectedRobot
    tool_frame: str
    rigid: frozenset[str]  # the links no joint of the query moves relative to the tool
    hand: HandContact | None  # what the hand may touch, and how deep
    position_tolerance: float  # [m]
    orientation_tolerance: float  # [rad]

    def __call__(self, hits: Sequence[LinkPair]) -> None:
        world = self.robot.world
        body = world.object(self.robot.name)
        tool = world.link_pose(body, self.tool_frame).position
        radii = world.contacts.link_radii(body)
        for link, named in hits:
            if link not in self.rigid or named in body.link_index:
                continue
            reach = math.dist(world.link_pose(body, link).position, tool) + radii[link]
            bound = 2 * (self.position_tolerance + self.orientation_tolerance * reach)
            bound += MISS_MARGIN
            if self.hand is not None and self.hand.covers(link, named):
                bound += self.hand.depth
            depth = contact_depth(world, body, link, named)
            if depth > bound:
                raise CertainMiss(
                    f"{link} is {depth * 1000:.1f} mm in {named}: deeper than any solution "
                    f"of the query can take it out of ({bound * 1000:.1f} mm)",
                    colliding_pairs=((link, named),), depth=depth, bound=bound,
                )  # fmt: skip


def rigid_links(model: RobotModel, tool_frame: str, moving: tuple[str, ...]) -> frozenset[str]:
    """The links that keep their place relative to ``tool_frame`` while the joints
    ``moving`` (and their mimic followers) move: below the last of them above the tool,
    and below none of them; empty when the tool is below none. Kept with the model."""
    return model.derived(_RigidLinks).of(tool_frame, moving)


@dataclass
class _RigidLinks:
    """Per tool frame and set of moving joints: the links rigid with the tool. They
    follow from the model alone, so they are kept with it (``RobotModel.derived``)."""

    model: RobotModel
    _found: dict[tuple[str, tuple[str, ...]], frozenset[str]] = field(default_factory=dict)

    def of(self, tool_frame: str, moving: tuple[str, ...]) -> frozenset[str]:
        key = (tool_frame, moving)
        found = self._found.get(key)
        if found is None:
            found = self._found.setdefault(key, self._below(tool_frame, set(moving)))
        return found

    def _below(self, tool_frame: str, moving: set[str]) -> frozenset[str]:
        joints = self.model.joints
        moved = moving | {
            name for name, joint in joints.items()
            if joint.mimic is not None and joint.mimic.joint in moving
        }  # fmt: skip
        parent_joint = {joint.child: name for name, joint in joints.items()}
        top = tool_frame
        while top in parent_joint and parent_joint[top] not in moved:
            top = joints[parent_joint[top]].parent
        if top not in parent_joint:
            return frozenset()
        children: dict[str, list[tuple[str, str]]] = {}
        for name, joint in joints.items():
            children.setdefault(joint.parent, []).append((name, joint.child))
        found, todo = {top}, [top]
        while todo:
            for name, child in children.get(todo.pop(), ()):
                if name not in moved and child not in found:
                    found.add(child)
                    todo.append(child)
        return frozenset(found)
