"""Whether two versions set a breakfast table the same way, write for write.

``trajectory_identity.py`` covers kitchen transports; a breakfast also opens and closes
drawers and doors, carries two things at once and plans round more. This runs one PR2
breakfast for two (``setting-table``, ``activity_bench.variant(seed)``) after the scene is
built and prints a hash of every joint and pose write the world sees, in order (checks
included: an optimisation that must not change what is checked keeps it), their count and
a hash of the final state. Run it on the old and the new checkout
(``PYTHONPATH=<checkout>/src``) and compare the two lines.

``moves`` hashes the writes outside ``move_tcp``'s IK queries (their candidates' checks,
put back before the query returns) and outside the looks of ``bar_opening._reaches`` (IK
with the fingers set part-way, all put back): an optimisation that skips checks whose answer is
certain (a query sure to fail whose failure nobody reads) changes ``hash`` by the checks
it skips, and must keep ``moves`` and ``final``.

Usage: python benchmarks/breakfast_fingerprint.py [seed] [robot]   (defaults 0, pr2)
"""

from __future__ import annotations

import hashlib
import sys
from collections.abc import Mapping
from typing import Any

from activity_bench import _timed, variant

from robocram.projection import arm, bar_opening
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import PoseLike
from robocram.world.world_tables import ClampedJoint, ObjectRef, WorldTables


class _Writes:
    """The world's joint and pose writes, hashed in order: all, and those outside IK."""

    def __init__(self) -> None:
        self.digest = hashlib.sha256()
        self.moves = hashlib.sha256()
        self.joints = 0
        self.poses = 0
        self.in_ik = 0  # depth of IK queries (arm._solve, bar_opening._reaches) being run

    def add(self, obj: ObjectRef, what: object) -> None:
        text = repr((getattr(obj, "name", obj), what)).encode()
        self.digest.update(text)
        if not self.in_ik:
            self.moves.update(text)


def main() -> None:
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 0
    robot = sys.argv[2] if len(sys.argv) > 2 else "pr2"
    kept, places = variant(seed)
    scene = breakfast_scene(robot, places=places, kept=kept)
    writes = _Writes()
    set_joints, set_pose = WorldTables.set_joint_states, WorldTables.set_pose

    def joints(
        self: WorldTables, obj: ObjectRef, values: Mapping[str, float], carry: bool = True
    ) -> list[ClampedJoint]:
        writes.add(obj, sorted(values.items()))
        writes.joints += 1
        return set_joints(self, obj, values, carry)

    def placed(self: WorldTables, obj: ObjectRef, pose: PoseLike) -> None:
        writes.add(obj, pose)
        writes.poses += 1
        set_pose(self, obj, pose)

    solve = arm._solve

    def solving(*args: Any, **keys: Any) -> Any:
        writes.in_ik += 1
        try:
            return solve(*args, **keys)
        finally:
            writes.in_ik -= 1

    WorldTables.set_joint_states = joints  # type: ignore[method-assign]
    WorldTables.set_pose = placed  # type: ignore[method-assign]
    look = bar_opening._reaches

    def looking(*args: Any, **keys: Any) -> Any:
        writes.in_ik += 1
        try:
            return look(*args, **keys)
        finally:
            writes.in_ik -= 1

    arm._solve = solving
    bar_opening._reaches = looking
    try:
        ok, _, why = _timed(scene, "setting-table", people=2)
    finally:
        WorldTables.set_joint_states = set_joints  # type: ignore[method-assign]
        WorldTables.set_pose = set_pose  # type: ignore[method-assign]
        arm._solve = solve
        bar_opening._reaches = look
    world = scene.world
    final = repr(
        [(o.name, world.pose(o.name), sorted(world.joint_states(o.name).items())) for o in world]
    )
    print(
        f"{robot} seed {seed}: set {ok} {why}; writes {writes.joints} joint, {writes.poses} "
        f"pose; hash {writes.digest.hexdigest()[:16]}; "
        f"final {hashlib.sha256(final.encode()).hexdigest()[:16]}; "
        f"moves {writes.moves.hexdigest()[:16]}"
    )


if __name__ == "__main__":
    main()
