"""One robot of a world as the process modules see it: its body, description and frames.

Low-level functions take a :class:`ProjectedRobot`. It resolves stamped poses against
the world as it is now (``map``, any link of the robot, any object name), so process
modules never act on a stale transform snapshot, and it owns the lock that serialises
IK queries for this robot (the kinematics layer is not thread-safe).
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field

from robocram.motion import CarriedJoint, MotionSettings
from robocram.projection.arm_ways import ArmWays
from robocram.projection.errors import ProjectionError, unknown_name
from robocram.robots import ArmDescription, LoadedDescription
from robocram.tf import Pose, PoseLike, PoseStamped
from robocram.world import RobotHandle, RobotObject, World

MAP_FRAME = "map"


@dataclass(frozen=True)
class ProjectedRobot:
    """A robot in a projection world, with a lock guarding its IK solvers."""

    world: World
    name: str
    ik_lock: threading.Lock = field(default_factory=threading.Lock, compare=False)
    motion: MotionSettings = field(default_factory=MotionSettings, compare=False)
    carried: list[CarriedJoint] = field(default_factory=list, compare=False)
    """Other objects' joints the robot's next trajectories move along (a drawer its hand
    pulls: :mod:`~robocram.projection.articulation` sets them per step): reported with
    each trajectory, so a replay moves them too."""
    held_rolls: dict[tuple[str, str], float] = field(default_factory=dict, compare=False)
    """The grasp roll [rad] that last held each ``(part, handle)`` all the way, and
    ``("", arm)`` any handle with that arm: a drawer opened with one roll is closed with
    it first (:mod:`~robocram.projection.articulation`)."""
    held_pitches: dict[tuple[str, str], float] = field(default_factory=dict, compare=False)
    """The pitch [rad] from above with which each ``(part, handle)`` was last held, where
    the front failed: closing takes it so first."""
    arm_ways: ArmWays = field(default_factory=ArmWays, compare=False)
    """The last ways each arm came along, newest last (:mod:`~robocram.projection.arm_ways`):
    a hand let go where no new way out is free goes back along the one it came by."""
    ways_out: list[Pose] = field(default_factory=list, compare=False)
    """Where a differential base stood before it drove for an arm motion that then found
    no path (at most one, :func:`~robocram.projection.arm.move_tcp`): a later drive that
    finds no way from where it was left goes back there first
    (:func:`~robocram.projection.navigation.drive`)."""
    handle: RobotHandle = field(init=False, compare=False, repr=False)
    """The robot of the world, looked up once: what the motion layer takes."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "handle", RobotHandle.of(self.world, self.name))

    @classmethod
    def of(
        cls,
        world: World,
        robot: str | RobotObject | None = None,
        motion: MotionSettings | None = None,
    ) -> ProjectedRobot:
        """The robot ``robot`` of ``world`` (default: its only robot); ``motion`` says how
        its arm motions are planned (default: round obstacles, seed 0)."""
        settings = motion or MotionSettings()
        robots = world.robots()
        if robot is None:
            if len(robots) != 1:
                names = [r.name for r in robots]
                raise ProjectionError(
                    f"the world has {len(robots)} robots {names}; name the one to project"
                )
            return cls(world, robots[0].name, motion=settings)
        name = robot.name if isinstance(robot, RobotObject) else robot
        if name not in world or not any(r.name == name for r in robots):
            raise unknown_name("robot", name, "the world", [r.name for r in robots])
        return cls(world, name, motion=settings)

    @property
    def body(self) -> RobotObject:
        """The robot's body in the world."""
        return self.handle.body

    @property
    def description(self) -> LoadedDescription:
        """The robot's checked description (its model set)."""
        desc = self.body.description
        if not isinstance(desc, LoadedDescription):
            raise ProjectionError(
                f"robot {self.name!r} carries an unchecked description; add robots to the "
                "world with world.add_robot, which loads and checks it"
            )
        return desc

    @property
    def base_frame(self) -> str:
        """The URDF root link, the frame IK targets and perceived poses are given in."""
        return self.description.model.root_link

    def arm(self, arm: str) -> ArmDescription:
        """The arm called ``arm``, or an error naming the robot's arms."""
        spec = self.description.arms.get(arm)
        if spec is None or arm == self.description.neck_arm:
            arms = [a for a in self.description.arms if a != self.description.neck_arm]
            listed = ", ".join(repr(a) for a in arms) or "none"
            raise ProjectionError(
                f"{unknown_name('arm', arm, self.name, arms)}; its arms: {listed}"
            )
        return spec

    def base_pose(self) -> Pose:
        """The pose of the robot's root link in ``map``."""
        return self.world.pose(self.name)

    def frame_pose(self, frame: str) -> Pose:
        """Pose of ``frame`` (``map``, a link of this robot, or an object) in ``map``."""
        if frame == MAP_FRAME:
            return Pose()
        if frame in self.body.link_index:
            return self.world.link_pose(self.name, frame)
        if frame in self.world:
            return self.world.pose(frame)
        known = [MAP_FRAME, *self.body.link_index, *(o.name for o in self.world.objects())]
        raise unknown_name("frame", frame, f"the world of {self.name}", known)

    def in_map(self, pose: PoseStamped | PoseLike) -> Pose:
        """A stamped pose (any known frame) or a plain pose (taken as ``map``) in ``map``."""
        if isinstance(pose, PoseStamped):
            return self.frame_pose(pose.frame_id) * pose.pose
        return Pose.coerce(pose)

    def in_base(self, pose: PoseStamped | PoseLike) -> Pose:
        """The same pose relative to the robot's root link."""
        return self.base_pose().inverse() * self.in_map(pose)
