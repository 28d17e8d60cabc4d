"""Where the robot stands when an IK query starts: read once for every candidate it checks.

A candidate moves the links below its joints (the arm's, the torso's); the others stay
where they start, so what they touch is the same at every candidate of the query and is
asked once. So are the bounds of everything the robot may hit
(:meth:`~robocram.world.World.obstacle_boxes`: only the robot and what it holds move), the
self pairs apart at the start, and the joint values each candidate puts back. A check asks
:meth:`IKStart.holds` before each candidate and reads the start again if the robot stands
otherwise; nothing but the robot may move between its candidates.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import RobotModel
from robocram.world import ObstacleBoxes, WorldObject

LinkPair = tuple[str, str]  # (robot link, object or object/link | robot link)


@dataclass
class IKStart:
    """The robot's start for one query's checks; :meth:`colliding` tries a candidate."""

    robot: ProjectedRobot
    distance: float  # [m] closer than this is a collision
    state: tuple[float, ...]  # the robot's body state at the start
    joints: dict[str, float]  # the values to put back (mimic followers come with masters)
    unheld: frozenset[str]  # joints simulation does not hold where they are
    ignore: list[WorldObject]  # what may touch: the floor, what the robot holds
    obstacles: ObstacleBoxes | None  # None: what it holds carries more, ask the broadphase
    own: list[LinkPair]  # the self pairs to check, apart at the start
    _kept: dict[str, list[LinkPair]] = field(default_factory=dict)  # links that stay put
    _moves: dict[tuple[str, ...], tuple[frozenset[int], list[LinkPair]]] = field(
        default_factory=dict
    )

    @classmethod
    def read(
        cls, robot: ProjectedRobot, distance: float, own: Callable[[], list[LinkPair]]
    ) -> IKStart:
        """The start as it is now; ``own`` gives the self pairs apart now."""
        world = robot.world
        model = robot.description.model
        body = world.object(robot.name)
        joints = world.joint_states(body)
        held = world.held_joints(body)
        carried = set(world.attachments(body))
        ignore = [o for o in world.objects() if o.name in carried or o.type == "floor"]
        carries_more = any(a.robot in carried for a in world.all_attachments())
        return cls(
            robot,
            distance,
            world.body_state(body),
            {j: v for j, v in joints.items() if model.joints[j].mimic is None},
            frozenset(j for j, v in joints.items() if held.get(j) != v),
            ignore,
            None if carries_more else world.obstacle_boxes([body, *ignore]),
            own(),
        )

    def holds(self) -> bool:
        """Whether the robot stands as it did at the start (base and joints)."""
        return self.robot.world.body_state(self.robot.name) == self.state

    def colliding(
        self, joints: Mapping[str, float], allowed: set[str], base_moves: bool
    ) -> list[LinkPair]:
        """The ``(robot link, object)`` and self pairs in contact at ``joints``, links in
        ``allowed`` excepted, the robot put back after; ``base_moves``: every link moved."""
        world = self.robot.world
        body = world.object(self.robot.name)
        colliders = body.collider_names()
        moved, own = self._moved(body, tuple(joints), base_moves or self.obstacles is None)
        ask = [n for i, n in colliders.items() if i in moved or n not in self._kept]
        before = self._to_restore(joints)
        world.set_joint_states(body, dict(joints))
        try:
            found: dict[str, list[LinkPair]] = {n: [] for n in ask}
            for link, obj, other in world.link_pairs_in_contact(
                body, self.ignore, self.distance, ask, self.obstacles
            ):
                several = len(obj.link_index) > 1
                found[link].append((link, f"{obj.name}/{other}" if several else obj.name))
            if self.obstacles is not None and not base_moves:
                self._kept.update((n, found[n]) for i, n in colliders.items()
                                  if n in found and i not in moved)  # fmt: skip
            hits: dict[LinkPair, None] = {}
            for link in colliders.values():
                if link not in allowed:
                    hits.update(dict.fromkeys(found[link] if link in found else self._kept[link]))
            hits.update(dict.fromkeys(world.self_contacts(body, own, self.distance)))
            return list(hits)
        finally:
            world.set_joint_states(body, before)

    def _moved(
        self, body: WorldObject, joints: tuple[str, ...], everything: bool
    ) -> tuple[frozenset[int], list[LinkPair]]:
        """The link indices ``joints`` move (all if ``everything``), and the self pairs one
        of whose links moves (the others stay apart, as at the start)."""
        key = () if everything else joints
        found = self._moves.get(key)
        if found is None:
            if everything:
                indices = frozenset(body.link_index.values())
            else:
                links = self.robot.description.model.derived(_MovedLinks).below(joints)
                indices = frozenset(body.link_index[n] for n in links if n in body.link_index)
            own = [
                (a, b) for a, b in self.own
                if body.link_index[a] in indices or body.link_index[b] in indices
            ]  # fmt: skip
            found = self._moves[key] = (indices, own)
        return found

    def _to_restore(self, joints: Mapping[str, float]) -> dict[str, float]:
        """The values that put the robot back after it is set to ``joints``: those the
        candidate changes (mimic masters for their followers), and those simulation does
        not hold where they are (putting them back holds them there)."""
        model = self.robot.description.model
        mimics = (model.joints[j].mimic for j in joints)
        masters = {mimic.joint for mimic in mimics if mimic is not None}
        return {
            joint: value for joint, value in self.joints.items()
            if joint in joints or joint in masters or joint in self.unheld
        }  # fmt: skip


@dataclass
class _MovedLinks:
    """Per set of joints: the links below them and below their mimic followers. They
    follow from the model alone, so they are kept with it (``RobotModel.derived``)."""

    model: RobotModel
    _children: dict[str, list[str]] = field(default_factory=dict)
    _followers: dict[str, list[str]] = field(default_factory=dict)
    _found: dict[tuple[str, ...], frozenset[str]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for name, joint in self.model.joints.items():
            self._children.setdefault(joint.parent, []).append(joint.child)
            if joint.mimic is not None:
                self._followers.setdefault(joint.mimic.joint, []).append(name)

    def below(self, joints: tuple[str, ...]) -> frozenset[str]:
        """The links that move when ``joints`` do."""
        found = self._found.get(joints)
        if found is None:
            moving = list(joints)
            for joint in moving:
                moving.extend(self._followers.get(joint, ()))
            links = [self.model.joints[j].child for j in moving if j in self.model.joints]
            for link in links:
                links.extend(self._children.get(link, ()))
            found = self._found.setdefault(joints, frozenset(links))
        return found
