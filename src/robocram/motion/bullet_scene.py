"""Configuration checks on the projection world itself (PyBullet), for a few joints.

The robot is put at each configuration, asked for contacts through Bullet's broadphase,
and put back. Held objects are checked against the world too (they ride with the hand);
the robot touching what it holds, anything touching a floor, and the ``allowed_links``
(CRAM's ``allow_hand``) do not count. Slower than a coal snapshot, but it sees exactly
what projection sees: tests use it as the independent judge of planned paths.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence

from robocram.motion.configuration_checker import Configuration, LinkPair
from robocram.motion.errors import MotionError
from robocram.world import World, WorldObject


class BulletScene:
    """Checks configurations of ``joints`` of ``robot`` in ``world`` (one thread at a time)."""

    def __init__(
        self,
        world: World,
        robot: str,
        joints: Sequence[str],
        allowed_links: Collection[str] = (),
        distance: float = 0.0,
    ) -> None:
        self.world = world
        self.robot = robot
        self._joints = tuple(joints)
        known = world.joint_states(robot)
        unknown = [j for j in self._joints if j not in known]
        if unknown:
            raise MotionError(
                f"joints {unknown} are not movable joints of {robot}; known: {sorted(known)}"
            )
        self.allowed_links = frozenset(allowed_links)
        self.distance = distance  # [m] nearer than this counts as touching

    @property
    def joints(self) -> tuple[str, ...]:
        """The joints a configuration gives values for, in order."""
        return self._joints

    def colliding(self, q: Configuration, first_only: bool = False) -> list[LinkPair]:
        """The colliding ``(robot link, other)`` pairs at ``q`` (empty: free)."""
        values = dict(zip(self._joints, (float(v) for v in q), strict=True))
        return self.colliding_at(values, first_only)

    def colliding_at(self, values: Mapping[str, float], first_only: bool = False) -> list[LinkPair]:
        """The colliding pairs with the joints in ``values`` set (the others unchanged)."""
        world = self.world
        model = world.robot(self.robot).description.model
        before = {
            j: v for j, v in world.joint_states(self.robot).items() if model.joints[j].mimic is None
        }
        world.set_joint_states(self.robot, values)
        try:
            return self.colliding_now(first_only)
        finally:
            world.set_joint_states(self.robot, before)

    def is_free(self, q: Configuration) -> bool:
        """Whether ``q`` collides with nothing."""
        return not self.colliding(q, first_only=True)

    def colliding_now(self, first_only: bool = False) -> list[LinkPair]:
        """The colliding pairs of the robot (and what it holds) as it is in the world now."""
        world = self.world
        held = [world.object(name) for name in world.attachments(self.robot)]
        floors = world.objects("floor")
        hits: dict[LinkPair, None] = {}
        for link, obj, other_link in world.link_pairs_in_contact(
            self.robot, [*held, *floors], self.distance
        ):
            if link not in self.allowed_links:
                hits[(link, _named(world, obj, other_link))] = None
                if first_only:
                    return list(hits)
        for item in held:
            skip = [world.robot(self.robot), *(h for h in held if h is not item), *floors]
            for _, obj, other_link in world.link_pairs_in_contact(item, skip, self.distance):
                hits[(item.name, _named(world, obj, other_link))] = None
                if first_only:
                    return list(hits)
        return list(hits)


def _named(world: World, obj: WorldObject, link: str) -> str:
    """An object by its name, or ``object/link`` when it has several links."""
    return f"{obj.name}/{link}" if len(world.link_names(obj)) > 1 else obj.name
