"""How a traced robot is built again for a replay, an audit or an export.

In order: the description file the caller gives for it (checked against the URDF that ran),
the file it ran with if it is still there and still describes that URDF, the trace's own
copy of its description and URDF, and last its built-in name. A robot read from a file is
thus rebuilt with no option wherever the trace goes; only a trace of an older robocram,
which kept no copy, needs its file.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from robocram.robots import DescriptionError, RobotDescription
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import RobotNotRebuilt
from robocram.traces.robot_model_record import stored_description, urdf_digest
from robocram.world import RobotObject, World


def add_traced_robot(
    world: World,
    recipe: Mapping[str, object],
    robots: Mapping[str, str],
    db: TraceDatabase | None = None,
) -> RobotObject:
    """Add the recipe's robot to ``world`` as it ran (see the module's order).

    Raises:
        RobotNotRebuilt: the file given does not load or describes another URDF; or the
            trace keeps no copy and the file it ran with is gone, fails or changed.
    """
    robot, name = str(recipe["robot"]), str(recipe["name"])
    given = robots.get(robot)
    if given is not None:
        return _from_file(world, recipe, given)
    stored = str(recipe.get("source") or "")
    copy = _stored_copy(recipe, db)
    if stored and copy is None:
        return _from_file(world, recipe, stored)
    if stored and _still_there(stored):
        try:
            return _from_file(world, recipe, stored)
        except RobotNotRebuilt:
            pass  # moved, edited or broken since: the trace's copy is the robot that ran
    if copy is not None:
        return world.add_robot(copy, name=name)
    return world.add_robot(robot, name=name)


def _stored_copy(recipe: Mapping[str, object], db: TraceDatabase | None) -> RobotDescription | None:
    digest = recipe.get("description_digest")
    if db is None or not isinstance(digest, str):
        return None
    return stored_description(db, digest, str(recipe["urdf_digest"]), str(recipe["source"]))


def _still_there(source: str) -> bool:
    """Whether a ``FILE.py:NAME`` source's file exists (a module source is tried as is)."""
    where = source.partition(":")[0] if ".py" in source else ""
    return not where or Path(where).is_file()


def _from_file(world: World, recipe: Mapping[str, object], source: str) -> RobotObject:
    robot, name = str(recipe["robot"]), str(recipe["name"])
    try:
        handle = world.add_robot(source, name=name)
    except DescriptionError as err:
        raise RobotNotRebuilt(robot, source, f"does not load ({err})") from err
    if urdf_digest(handle.description.model) != recipe["urdf_digest"]:
        world.remove(handle)
        raise RobotNotRebuilt(robot, source, "now describes another URDF than the one that ran")
    return handle
