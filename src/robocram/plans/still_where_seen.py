"""A pick's try starts only where the object still lies where its grasps were aimed.

A pick computes its grasps once, from where the object was seen, and tries them in turn.
A try that fails after its fingers met the object can leave it elsewhere: the HSR's first
rim grasp of a bowl in a drawer pushed it 5.4 cm, the next grasp still caught the rim, off
its middle, and the bowl was carried as if held at its middle and put down 5.5 cm off its
seat. Such a try is refused before the hand moves, so that the pick fails with the cause
and the fetch perceives the object again from its next stand.
"""

from __future__ import annotations

from robocram.plans.grasp_failures import ObjectMovedSinceSeen
from robocram.tf import Pose, PoseStamped, TfError, transform_pose

MOVED = 0.01  # [m] an object this far from where it was seen has moved (fetch's STILL_THERE)


def still_where_seen(name: str, seen: Pose | None) -> None:
    """Refuse a try at ``name`` seen at ``seen`` (map) where it lies more than
    :data:`MOVED` from there now; nothing to check without a seen pose or a frame of it.

    Raises:
        ObjectMovedSinceSeen: it moved (its grasps would put the hand beside it).
    """
    if seen is None:
        return
    try:
        now = transform_pose(PoseStamped(name), "map").pose
    except TfError:
        return  # no frame of the object to compare (a real robot's object not tracked)
    moved = now.distance_to(seen)
    if moved > MOVED:
        raise ObjectMovedSinceSeen(
            f"{name!r} lies {moved:.3f} m from where it was seen, where this try's grasp "
            "was aimed: an earlier try moved it; perceive it again",
            object_name=name,
            moved=moved,
        )
