"""The tables of one world: its physics client, bodies, attachments and held joints.

:class:`WorldTables` owns one pybullet client and the tables beside it (the bodies by
name and body id, joint limits, attachments, the joint values robots are held at, the
change counters) and is the only class that writes them: creating and removing bodies,
placing them, setting joints and stepping all go through it. It is no public API: the
:class:`~robocram.world.world.World` facade answers the everyday questions with it, and
the world's parts (``bodies``, ``contacts``, ``physics``, ``snapshots``, ``view``) are
given it and use its public methods.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Mapping, Sequence
from typing import Protocol

from robocram.robots import RobotModel, mimic_followers
from robocram.tf import Pose, PoseLike
from robocram.world.attachment import Attachment, check_acyclic
from robocram.world.body_loading import create_body
from robocram.world.body_slots import (
    index_body,
    link_slot,
    part_joint_states,
    reset_joints,
    reset_slots,
)
from robocram.world.body_spec import BodySpec
from robocram.world.derived import Derived
from robocram.world.errors import (
    DuplicateObjectError,
    NotARobotError,
    UnknownJointError,
    UnknownObjectError,
    WorldClosedError,
    WorldError,
    WorldValueError,
)
from robocram.world.held_motors import HeldMotors
from robocram.world.joint_state import ClampedJoint, JointLimits, clamp_values
from robocram.world.pybullet_backend import pybullet
from robocram.world.versions import Versions
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.written_bases import BaseInput, Vector, WrittenBases
from robocram.world.written_joints import WrittenJoints

ObjectRef = WorldObject | str


class BodyHook(Protocol):
    """What is told when a body joins or leaves the tables (the facade's knowledge base)."""

    def inserted(self, handle: WorldObject) -> None:
        """``handle``'s body is in the world now."""

    def removed(self, handle: WorldObject, robots: list[RobotObject]) -> None:
        """``handle``'s body left the world, which still holds ``robots``."""


ORIGIN = Pose()


class WorldTables:
    """One pybullet client, its named bodies, attachments and the joints robots hold."""

    def __init__(
        self,
        gui: bool = False,
        gravity: float = -9.81,
        time_step: float = 1 / 240,
        hook: BodyHook | None = None,
    ):
        check_time_step(time_step)
        if not math.isfinite(gravity):
            raise WorldValueError(f"gravity must be a finite number [m/s^2], got {gravity!r}")
        try:
            self.client: int = pybullet.connect(pybullet.GUI if gui else pybullet.DIRECT)
        except pybullet.error as err:
            raise WorldError(f"pybullet could not connect: {err}") from err
        if self.client < 0:
            raise WorldError(
                "pybullet could not open a GUI (it allows one per process and needs a "
                "display); use World() for a headless world"
                if gui
                else "pybullet could not start a physics client"
            )
        self.gravity = gravity  # [m/s^2] along z
        self.time_step = time_step  # [s] per physics step
        self.time = 0.0  # [s] simulated so far
        pybullet.setGravity(0, 0, gravity, physicsClientId=self.client)
        pybullet.setTimeStep(time_step, physicsClientId=self.client)
        self._objects: dict[str, WorldObject] = {}
        self._limits: dict[tuple[int, str], JointLimits] = {}  # (body, joint): fixed at load
        self._inertial: dict[str, Pose] = {}  # base link frame -> pybullet base (COM) frame
        self._part_bases: dict[str, tuple[Pose, ...]] = {}  # a cut model's: root -> part base
        self._owners: dict[int, WorldObject] = {}  # every body id (parts too) -> its object
        self._attachments: dict[str, Attachment] = {}  # by attached object name
        self._holds: dict[str, dict[int, float]] = {}  # robot -> joint index -> held value
        self._written = WrittenJoints()  # bodies whose joints stand as last written
        self._bases = WrittenBases()  # objects whose bases stand as last written
        self._motors = HeldMotors()  # a robot's held joints need no motor
        self._versions = Versions()  # stamped by every write below
        self._stepping: Derived[None, tuple[list[str], list[str]]] = Derived(_structure)
        self._hook = hook  # told of each body added or removed (the knowledge base's facts)

    @property
    def versions(self) -> Versions:
        """The world's change counters: per body its pose and joints, and the structure
        (what a cache compares instead of states; see :mod:`robocram.world.derived`)."""
        return self._versions

    def close(self) -> None:
        """Disconnect the physics client; the world is unusable afterwards."""
        if self.client >= 0:
            pybullet.disconnect(physicsClientId=self.client)
            self.client = -1

    @property
    def closed(self) -> bool:
        """Whether :meth:`close` was called."""
        return self.client < 0

    def physics_client(self) -> int:
        """The pybullet client id, for the world's own helper modules; closed: an error."""
        if self.client < 0:
            raise WorldClosedError()
        return self.client

    def add_object(
        self, name: str, type: str, spec: BodySpec, pose: PoseLike = ORIGIN
    ) -> WorldObject:  # noqa: A002
        """Add a body made from ``spec``, called ``name``, of type ``type``, at ``pose``."""
        handle = WorldObject(name, type, -1, spec)
        self.insert(handle, pose)
        return handle

    def insert(self, handle: WorldObject, pose: PoseLike = ORIGIN) -> WorldObject:
        """Create ``handle``'s body from its spec, index it, place it at ``pose``; return it.

        The handle may be one removed earlier: it gets a new body and keeps its identity.
        """
        if handle.name in self._objects:
            raise DuplicateObjectError(handle.name)
        cid = self.physics_client()
        loaded = create_body(handle.name, handle.spec, cid)
        handle.body_id = loaded.bodies[0]
        several = len(loaded.bodies) > 1
        handle.parts = loaded.bodies if several else ()
        handle.part_offsets = loaded.offsets if several else ()
        handle.urdf_model = loaded.model
        self._motors.forget(handle.body_id)
        dyn = pybullet.getDynamicsInfo(handle.body_id, -1, physicsClientId=cid)
        self._inertial[handle.name] = Pose(dyn[3], dyn[4])
        if several:
            self._part_bases[handle.name] = tuple(
                offset * Pose(*pybullet.getDynamicsInfo(body, -1, physicsClientId=cid)[3:5])
                for body, offset in zip(loaded.bodies, loaded.offsets, strict=True)
            )
        handle.joint_index.clear()
        handle.link_index.clear()
        handle.movable_joints.clear()
        handle.forget_indices()
        for body in handle.bodies:
            self._owners[body] = handle
            index_body(handle, body, cid)
        handle.link_offset.clear()
        for frame, host, host_T_frame in getattr(handle.spec, "frames", ()):
            handle.link_index[frame] = handle.link_index[host]
            handle.link_offset[frame] = host_T_frame
        handle.colliders = frozenset(
            i for i in handle.index_names()
            if pybullet.getCollisionShapeData(*handle.locate(i), physicsClientId=cid)
        )  # fmt: skip
        self._objects[handle.name] = handle
        self._versions.added(handle.name)
        if handle.joint_index:
            self._holds[handle.name] = {}
        self.set_pose(handle, pose)
        if self._hook is not None:
            self._hook.inserted(handle)
        return handle

    def object(self, name: ObjectRef) -> WorldObject:
        """The object called ``name`` (a handle is checked to still belong to this world)."""
        key = name.name if isinstance(name, WorldObject) else name
        found = self._objects.get(key)
        if found is None:
            raise UnknownObjectError(key, self._objects)
        return found

    def robot(self, name: ObjectRef) -> RobotObject:
        """The robot called ``name``."""
        obj = self.object(name)
        if not isinstance(obj, RobotObject):
            raise NotARobotError(obj.name)
        return obj

    def owner(self, body: int) -> WorldObject | None:
        """The object a pybullet body id (a part's too) belongs to; None if no object's."""
        return self._owners.get(body)

    def objects(self, type: str | None = None) -> list[WorldObject]:  # noqa: A002
        """All objects in creation order, or those of one ``type``."""
        return [o for o in self._objects.values() if type is None or o.type == type]

    def robots(self) -> list[RobotObject]:
        """All robots in creation order."""
        return [o for o in self._objects.values() if isinstance(o, RobotObject)]

    def __contains__(self, name: ObjectRef) -> bool:
        key = name.name if isinstance(name, WorldObject) else name
        return key in self._objects

    def __iter__(self) -> Iterator[WorldObject]:
        return iter(list(self._objects.values()))

    def remove(self, obj: ObjectRef) -> None:
        """Take ``obj`` out of the world, with its attachments (either end)."""
        handle = self.object(obj)
        for name, att in list(self._attachments.items()):
            if handle.name in (name, att.robot):
                del self._attachments[name]
        for body in handle.bodies:
            pybullet.removeBody(body, physicsClientId=self.physics_client())
            self._owners.pop(body, None)
        self._motors.forget(handle.body_id)
        self._limits = {k: v for k, v in self._limits.items() if k[0] != handle.body_id}
        del self._objects[handle.name]
        self._inertial.pop(handle.name, None)
        self._part_bases.pop(handle.name, None)
        self._holds.pop(handle.name, None)
        self._written.forget(handle.name)
        self._bases.forget(handle.name)
        self._versions.removed(handle.name)
        if self._hook is not None:
            self._hook.removed(handle, self.robots())

    def pose(self, obj: ObjectRef) -> Pose:
        """Pose of the object's root link frame in the world."""
        handle = self.object(obj)
        pos, orn = pybullet.getBasePositionAndOrientation(
            handle.body_id, physicsClientId=self.physics_client()
        )
        return Pose(pos, orn) * self._inertial[handle.name].inverse()

    def set_pose(self, obj: ObjectRef, pose: PoseLike) -> None:
        """Teleport ``obj`` (at rest) to ``pose``; its attached objects follow.

        Placing an attached object moves it relative to its link; it stays attached.
        """
        handle = self.object(obj)
        self._place(handle, Pose.coerce(pose))
        att = self._attachments.get(handle.name)
        if att is not None:
            link_pose = self.link_pose(att.robot, att.link)
            self._attachments[handle.name] = Attachment(
                att.obj, att.robot, att.link, link_pose.inverse() * Pose.coerce(pose)
            )
            self._versions.restructured()  # held the same, at another grip
        self._follow(handle.name)

    def _place(self, handle: WorldObject, pose: Pose) -> None:
        """Put every body of ``handle`` at rest with its root link frame at ``pose``."""
        bases = self._part_bases.get(handle.name) or (self._inertial[handle.name],)
        written = []
        for body, base_in_root in zip(handle.bodies, bases, strict=True):
            base = pose * base_in_root
            written.append((body, base.position, base.orientation))
        self.put_bases(handle, written)

    def put_bases(self, handle: WorldObject, bases: Sequence[BaseInput]) -> None:
        """Write ``handle``'s bodies' bases (body id, COM position, orientation), at rest."""
        cid = self.physics_client()
        for body, position, orientation in bases:
            pybullet.resetBasePositionAndOrientation(
                body, position, orientation, physicsClientId=cid
            )
            pybullet.resetBaseVelocity(body, (0, 0, 0), (0, 0, 0), physicsClientId=cid)
        self._versions.moved(handle.name)
        self.wrote_bases(handle, bases)

    def wrote_bases(self, handle: WorldObject, bases: Sequence[BaseInput]) -> None:
        """``handle``'s bases were just written with ``bases`` (its pose counter moved):
        keep the inputs, which a snapshot writes again to stand exactly here."""
        self._bases.wrote(handle.name, self._versions, bases)

    def base_inputs(self, handle: WorldObject) -> dict[int, tuple[Vector, Vector]]:
        """The inputs the tables last wrote ``handle``'s bases with, by body id, while it
        stands so; empty once physics moved it (see :mod:`~robocram.world.written_bases`)."""
        return self._bases.inputs(handle.name, self._versions)

    def link_pose(self, obj: ObjectRef, link: str) -> Pose:
        """Pose of ``link`` (a URDF link or a frame added in code) in the world."""
        handle = self.object(obj)
        index = self._link_index(handle, link)
        offset = handle.link_offset.get(link, ORIGIN)
        if index < 0:
            return self.pose(handle) * offset
        body, at = handle.locate(index)
        if at < 0:  # a part's root link, fixed in the root link's frame
            return self.pose(handle) * handle.part_offsets[handle.parts.index(body)] * offset
        state = pybullet.getLinkState(
            body, at, computeForwardKinematics=True, physicsClientId=self.physics_client()
        )
        return Pose(state[4], state[5]) * offset

    def link_names(self, obj: ObjectRef) -> list[str]:
        """Names of all links and frames of ``obj``, the root first."""
        return list(self.object(obj).link_index)

    def _link_index(self, handle: WorldObject, link: str) -> int:
        return link_slot(handle, link)

    def joint_limits(self, obj: ObjectRef, joint: str) -> JointLimits:
        """Position limits [rad | m] of a movable joint; continuous ones are -inf/inf."""
        handle = self.object(obj)
        cached = self._limits.get((handle.body_id, joint))
        if cached is not None:
            return cached
        limits = self._joint_limits(handle, joint)
        self._limits[(handle.body_id, joint)] = limits
        return limits

    def _joint_limits(self, handle: WorldObject, joint: str) -> JointLimits:
        index = self._movable_index(handle, joint)
        if isinstance(handle, RobotObject):
            spec = handle.description.model.joints[joint]
            lower = -math.inf if spec.lower is None else spec.lower
            upper = math.inf if spec.upper is None else spec.upper
            return JointLimits(lower, upper)
        info = pybullet.getJointInfo(*handle.locate(index), physicsClientId=self.physics_client())
        if info[8] > info[9]:  # pybullet marks unlimited joints with lower > upper
            return JointLimits(-math.inf, math.inf)
        return JointLimits(info[8], info[9])

    def _movable_index(self, handle: WorldObject, joint: str) -> int:
        index = handle.joint_index.get(joint)
        movable = self._movable_names(handle)
        if index is None:
            raise UnknownJointError(handle.name, joint, movable)
        if joint not in movable:
            why = f"joint {joint!r} of {handle.name} is fixed and has no state"
            raise UnknownJointError(handle.name, joint, movable, why)
        return index

    def _movable_names(self, handle: WorldObject) -> list[str]:
        self.physics_client()  # a closed world answers with its typed error
        return list(handle.movable_joints)

    def joint_states(self, obj: ObjectRef) -> dict[str, float]:
        """Every movable joint's value [rad | m] by name."""
        handle = self.object(obj)
        names = self._movable_names(handle)
        cid = self.physics_client()
        if handle.parts:
            return part_joint_states(handle, names, cid)
        indices = [handle.joint_index[n] for n in names]
        states = pybullet.getJointStates(handle.body_id, indices, physicsClientId=cid)
        return {n: float(s[0]) for n, s in zip(names, states or (), strict=True)}

    def set_joint_states(
        self, obj: ObjectRef, values: Mapping[str, float], carry: bool = True
    ) -> list[ClampedJoint]:
        """Set joints by name, clamped to their limits; mimic joints follow their masters.

        Returns the joints whose requested value was outside the limits (empty if none).
        The values are held during simulation; attached objects follow unless ``carry`` is
        False: a check that puts the joints back before anything else looks, and ignores
        what the robot holds, saves moving it there and back.
        """
        handle = self.object(obj)
        kept, body = self._limits, handle.body_id
        limits = {n: kept.get((body, n)) or self.joint_limits(handle, n) for n in values}
        applied, clamped = clamp_values(values, limits)
        applied.update(self._mimic_values(handle, applied))
        by_index = {handle.joint_index[name]: value for name, value in applied.items()}
        held = self._holds.get(handle.name)
        if not self._written.already(handle.name, self._versions, held, by_index):
            reset_slots(handle, by_index, self.physics_client())
        self._versions.jointed(handle.name)
        self._holds.setdefault(handle.name, {}).update(by_index)
        self._written.wrote(handle.name, self._versions)
        if carry:
            self._follow(handle.name)
        return clamped

    def _mimic_values(self, handle: WorldObject, applied: dict[str, float]) -> dict[str, float]:
        if not isinstance(handle, RobotObject):
            return {}
        model = handle.description.model
        if model is None or applied.keys().isdisjoint(model.derived(_mimic_masters)):
            return {}  # nothing set has followers (asking would walk every joint twice)
        followers = mimic_followers(model, applied)
        out: dict[str, float] = {}
        for name, value in followers.items():
            if name in applied or name not in handle.joint_index:
                continue
            out[name] = self.joint_limits(handle, name).clamp(float(value))
        return out

    def attach(self, obj: ObjectRef, robot: ObjectRef, link: str) -> None:
        """Fix ``obj`` to ``link`` of ``robot`` at their current relative pose."""
        handle = self.object(obj)
        carrier = self.object(robot)
        if handle is carrier:
            raise WorldValueError(f"cannot attach {handle.name!r} to itself")
        check_acyclic(self._attachments, handle.name, carrier.name)
        link_pose = self.link_pose(carrier, link)
        rel = link_pose.inverse() * self.pose(handle)
        self._attachments[handle.name] = Attachment(handle.name, carrier.name, link, rel)
        self._versions.restructured()

    def detach(self, obj: ObjectRef) -> None:
        """Let ``obj`` go; it stays where it is. Detaching a free object is an error."""
        handle = self.object(obj)
        if self._attachments.pop(handle.name, None) is None:
            raise WorldValueError(f"{handle.name!r} is not attached to anything; nothing to detach")
        self._versions.restructured()

    def all_attachments(self) -> list[Attachment]:
        """Every attachment of the world, in the order they were made."""
        return list(self._attachments.values())

    def set_attachments(self, attachments: Iterable[Attachment]) -> None:
        """Replace every attachment by ``attachments`` (kept relative poses, nothing moves)."""
        new: dict[str, Attachment] = {}
        for att in attachments:
            self._link_index(self.object(att.robot), att.link)
            check_acyclic(new, self.object(att.obj).name, att.robot)
            new[att.obj] = att
        self._attachments = new
        self._versions.restructured()

    def held_joints(self, obj: ObjectRef) -> dict[str, float]:
        """The joint values [rad | m] that simulation holds ``obj``'s joints at, by name."""
        handle = self.object(obj)
        names = {i: n for n, i in handle.joint_index.items()}
        return {names[i]: v for i, v in self._holds.get(handle.name, {}).items()}

    def set_held_joints(self, obj: ObjectRef, values: Mapping[str, float]) -> None:
        """Hold exactly ``values`` (joint name -> [rad | m]) from now on; nothing moves now."""
        handle = self.object(obj)
        movable = set(self._movable_names(handle))
        for name in values:
            if name not in movable:
                self._movable_index(handle, name)  # raises the typed error naming it
        self._holds[handle.name] = {handle.joint_index[n]: float(v) for n, v in values.items()}
        self._written.forget(handle.name)  # the holds are not what PyBullet stands at

    def _follow(self, carrier: str) -> None:
        """Re-place the objects attached to ``carrier`` (and theirs, recursively)."""
        for att in list(self._attachments.values()):
            if att.robot != carrier:
                continue
            target = self._objects[att.obj]
            self._place(target, self.link_pose(carrier, att.link) * att.link_T_obj)
            self._follow(att.obj)

    def step(self) -> None:
        """Advance physics one time step; robots hold their joints, attachments follow.

        Held joints of robots are put back after the step, so their motors are off.
        """
        cid = self.physics_client()
        robots = [(self._objects[n].body_id, held) for n, held in self._holds.items()
                  if isinstance(self._objects[n], RobotObject)]  # fmt: skip
        for body, held in robots:
            self._motors.match(body, held.keys(), self.time_step, cid)
        pybullet.stepSimulation(physicsClientId=cid)
        self.time += self.time_step
        self._versions.stepped(*self._stepping.get(None, self._stepped, self._versions))
        for body, held in robots:
            reset_joints(body, held, cid)
        for carrier in {a.robot for a in self._attachments.values()}:
            self._follow(carrier)

    def _stepped(self) -> tuple[list[str], list[str]]:
        """The objects a physics step may move (all but static ones; a cut model's parts
        are bodies of their own), and those whose joints it may change (all with some)."""
        objects = self._objects.values()
        return (
            [o.name for o in objects if not o.is_static or o.parts],
            [o.name for o in objects if o.movable_joints],
        )


def _mimic_masters(model: RobotModel) -> frozenset[str]:
    """The joints some mimic joint of ``model`` follows."""
    return frozenset(j.mimic.joint for j in model.joints.values() if j.mimic is not None)


def _structure(versions: Versions, key: None) -> int:
    return versions.structure


def check_time_step(time_step: float) -> None:
    if not (time_step > 0 and math.isfinite(time_step)):
        raise WorldValueError(
            f"time_step must be a finite number of seconds > 0 (e.g. 1/240), got {time_step!r}"
        )
