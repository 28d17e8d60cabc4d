"""One grasp: where the tool goes relative to the object, how it comes in and lifts.

A grasp is robot-independent in what it asks (a side to come from, an opening) and
robot-specific only in the tool orientation, which maps the hand's approach and opening
axes (:class:`~robocram.grasping.hand.Hand`) onto the grasp's.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat


@dataclass(frozen=True)
class Grasp:
    """A grasp of an object by one hand, in the object's frame.

    Attributes:
        name: CRAM's name of the side it grasps from: top, front, left, right, rim, handle
            (and a suction hand's side).
        turn: [rad] the hand's turn about its approach axis (candidates of one grasp).
        tool: the tool frame's pose in the object's frame when grasping.
        approach: unit direction [object frame] the tool moves in to grasp.
        pre_grasp: [m] the tool starts this far back along ``approach``.
        lift: [m] the object is lifted this far up after gripping.
        opening: [m] the opening the hand needs (object width plus clearance).
        across: unit direction [object frame] the fingers spread along.
        tilt: [rad] a palm hand's rim grasp turned this far about the held wall, its wrist
            raised (0: flat); tried after the flat ones of its side.
        deeper: [m] a deep rim grasp's tool frame lies this far below the rim grasp's
            (0: not deep); tried after every other grasp of its name.
        raised: [m] a rim grasp raised this far so the hand, closing, keeps over the
            object's bottom (a palm hand's) or floor (fingers reaching past the tool
            frame) (0: not raised); tried after every other grasp.
        lift_back: [m] the lift also draws the tool this far back along ``approach`` (0:
            straight up): a suction hand's side touch slides the object out towards the
            arm as it rises, where an arm reaching over a counter has no room to rise.
    """

    name: str
    turn: float
    tool: Pose
    approach: Vector3
    pre_grasp: float
    lift: float
    opening: float
    across: Vector3
    tilt: float = 0.0
    deeper: float = 0.0
    lift_back: float = 0.0
    raised: float = 0.0

    def pre_grasp_tool(self) -> Pose:
        """The tool's pose [object frame] before it moves in."""
        x, y, z = self.tool.position
        ax, ay, az = self.approach
        d = self.pre_grasp
        return Pose((x - ax * d, y - ay * d, z - az * d), self.tool.orientation)

    def in_map(self, object_in_map: Pose) -> tuple[Pose, Pose, Pose]:
        """Grasp, pre-grasp and lifted tool poses in the map for the object there."""
        grasp = object_in_map * self.tool
        x, y, z = grasp.position
        if self.lift_back:
            ax, ay, _ = quat.rotate(object_in_map.orientation, self.approach)
            x, y = x - ax * self.lift_back, y - ay * self.lift_back
        lifted = Pose((x, y, z + self.lift), grasp.orientation)
        return grasp, object_in_map * self.pre_grasp_tool(), lifted
