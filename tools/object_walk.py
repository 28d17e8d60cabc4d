"""The walk of one object through a kitchen transport: the rooms it passes, the hops between
plans and execution, and the names it is called by (issue 39's last measure).

A profile hook watches every call into robocram while the PR2 carries the mug to the
table. A call *carries the object* when one of its arguments is the object's name, its
world body, or a value that names it (an ``object_name`` or ``name`` attribute equal to
it; a designator with a property that is or names it, nested designators included). Per
such call it notes the layer (the package under ``robocram``: a *room*) and the
parameter's name. Printed:

- rooms: the layers the object is handed through;
- hops: in the order of those calls, moves from ``plans`` to ``execution`` and back
  (the room sequence with repeats collapsed, every other room left out);
- names: the distinct parameter names the object is passed as.

Usage: python tools/object_walk.py [--list]
"""

from __future__ import annotations

import sys
from collections import Counter
from types import FrameType

OBJECT = "mug-1"


def _names_object(value: object, depth: int = 2) -> bool:
    """Whether ``value`` is the object or a value that names it (a designator: one of its
    properties, nested designators included)."""
    if isinstance(value, str):
        return value == OBJECT
    if depth == 0:
        return False
    for attr in ("object_name", "name"):
        try:
            found = getattr(value, attr, None)
        except Exception:  # a property that cannot answer here names nothing
            return False
        if isinstance(found, str) and found == OBJECT:
            return True
    props = getattr(value, "properties", None)
    return isinstance(props, tuple) and any(
        isinstance(pair, tuple) and len(pair) == 2 and _names_object(pair[1], depth - 1)
        for pair in props
    )


class Walk:
    """The calls that carried the object, in order: (room, module, function, parameter)."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, str, str, str]] = []

    def __call__(self, frame: FrameType, event: str, arg: object) -> None:
        if event != "call":
            return
        module = frame.f_globals.get("__name__", "")
        if not module.startswith("robocram."):
            return
        code = frame.f_code
        params = code.co_varnames[: code.co_argcount + code.co_kwonlyargcount]
        local = frame.f_locals
        for param in params:
            if param != "self" and param in local and _names_object(local[param]):
                room = module.split(".")[1]
                self.calls.append((room, module, code.co_name, param))


def walk() -> Walk:
    """Run the PR2's mug transport in the kitchen under the hook."""
    from robocram.designators import a
    from robocram.plans.transport import transport
    from robocram.projection import simulated_robot
    from robocram.scenes import kitchen_scene

    scene = kitchen_scene("pr2")
    seen = Walk()
    try:
        with simulated_robot(scene.world, scene.robot):
            sys.setprofile(seen)
            try:
                transport("mug", a.location(on=("kitchen", "table_top"), for_=OBJECT))
            finally:
                sys.setprofile(None)
    finally:
        scene.world.close()
    return seen


def hops(rooms: list[str]) -> tuple[int, int]:
    """Moves plans -> execution and execution -> plans in ``rooms`` (others left out)."""
    path = [r for r in rooms if r in ("plans", "execution")]
    path = [r for i, r in enumerate(path) if i == 0 or r != path[i - 1]]
    steps = list(zip(path[:-1], path[1:], strict=True))
    return steps.count(("plans", "execution")), steps.count(("execution", "plans"))


def main(argv: list[str]) -> None:
    seen = walk()
    rooms = Counter(room for room, *_ in seen.calls)
    names = Counter(param for *_, param in seen.calls)
    there, back = hops([room for room, *_ in seen.calls])
    print(f"rooms  {len(rooms):4d}  {', '.join(sorted(rooms))}")
    print(f"hops   {there:4d} plans -> execution, {back} execution -> plans")
    print(f"names  {len(names):4d}  {', '.join(sorted(names))}")
    print(f"calls  {len(seen.calls):4d}")
    if "--list" in argv:
        for room, count in rooms.most_common():
            print(f"    {room:14s} {count}")
        for name, count in names.most_common():
            print(f"    {name:20s} {count}")


if __name__ == "__main__":
    main(sys.argv[1:])
