"""The world as predicates of its own knowledge base: the implementations of the table's rows.

The predicates, their arguments and meanings are declared in
``robocram.knowledge.world_predicates``; here is one Python function per row, registered
by the table (:func:`robocram.knowledge.register_predicates`), which refuses a row left
without a function or a function without a row. Every predicate takes the world first;
unbound names enumerate. CRAM's ``assert`` forms are named so as not to clash with
Prolog's own.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from robocram.knowledge import Source, register_predicates
from robocram.knowledge.registration import Implementation
from robocram.logic import KnowledgeBase, Value, Var
from robocram.logic.limits import current_stop_check
from robocram.tf import Pose
from robocram.world.predicate_world import PredicateWorld

Solutions = Iterator[tuple[Value, ...] | None]


def world_knowledge_base(world: PredicateWorld) -> KnowledgeBase:
    """A new knowledge base with the predicates of ``world``."""
    kb = KnowledgeBase()
    implementations: dict[str, Implementation] = {}
    for part in (_objects, _robots, _attachments, _reasoning):
        implementations.update(part(world))
    register_predicates(kb, Source.WORLD, implementations)
    return kb


def _names(world: PredicateWorld, arg: object, robots_only: bool = False) -> list[str]:
    """The object names ``arg`` may stand for: all when unbound, else itself if it exists."""
    pool = world.robots() if robots_only else world.objects()
    if isinstance(arg, Var):
        return [o.name for o in pool]
    return [o.name for o in pool if o.name == arg]


def _ours(world: PredicateWorld, arg: object) -> bool:
    return isinstance(arg, Var) or arg is world


def _relation(world: PredicateWorld, test: Callable[[str, str], bool]) -> Callable[..., Solutions]:
    """A predicate ``p(W, A, B)`` enumerating the pairs of distinct objects for which
    ``test`` holds."""

    def solve(w: object, a: object, b: object) -> Solutions:
        if not _ours(world, w):
            return
        for name_a in _names(world, a):
            for name_b in _names(world, b):
                if name_a != name_b and test(name_a, name_b):
                    yield (world, name_a, name_b)

    return solve


def _objects(world: PredicateWorld) -> dict[str, Implementation]:
    def world_(w: object) -> Solutions:
        if _ours(world, w):
            yield (world,)

    def object_(w: object, name: object) -> Solutions:
        if _ours(world, w):
            yield from ((world, n) for n in _names(world, name))

    def object_type(w: object, name: object, kind: object) -> Solutions:
        if _ours(world, w):
            yield from ((world, n, world.object(n).type) for n in _names(world, name))

    def object_pose(w: object, name: object, pose: object) -> Solutions:
        if _ours(world, w):
            yield from ((world, n, world.pose(n)) for n in _names(world, name))

    def set_object_pose(w: object, name: Value, pose: Value) -> Solutions:
        if _ours(world, w) and not isinstance(name, Var):
            world.set_pose(name, Pose.coerce(_pose_value(pose)))
            yield None

    def simulate(w: object, seconds: Value) -> Solutions:
        if _ours(world, w):
            world.physics.simulate(float(seconds), stop_check=current_stop_check())  # a task's stop
            yield (world, seconds)

    def settle(w: object, name: Value, seconds: Value) -> Solutions:
        if _ours(world, w) and not isinstance(name, Var):
            world.physics.settle(name, float(seconds), stop_check=current_stop_check())
            yield (world, name, seconds)

    return {
        "world/1": world_,
        "object/2": object_,
        "object_type/3": object_type,
        "object_pose/3": object_pose,
        "set_object_pose/3": set_object_pose,
        "simulate/2": simulate,
        "settle/3": settle,
    }


def _pose_value(value: object) -> Value:
    """A pose given as a Pose or as Prolog lists ``[[X, Y, Z], [QX, QY, QZ, QW]]``."""
    if isinstance(value, list) and len(value) == 2 and isinstance(value[0], list):
        return (tuple(value[0]), tuple(value[1]))
    if isinstance(value, list):
        return tuple(value)
    return value


def _robots(world: PredicateWorld) -> dict[str, Implementation]:
    def robot(w: object, name: object) -> Solutions:
        if _ours(world, w):
            yield from ((world, n) for n in _names(world, name, robots_only=True))

    def joint_state(w: object, rob: object, joint: object, value: object) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob, robots_only=True):
            states = world.joint_states(name)
            joints = list(states) if isinstance(joint, Var) else [joint]
            yield from ((world, name, j, states[j]) for j in joints if j in states)

    def set_joint_state(w: object, rob: Value, joint: Value, value: Value) -> Solutions:
        if _ours(world, w):
            world.set_joint_states(rob, {joint: float(value)})
            yield None

    def link_pose(w: object, rob: Value, link: Value, pose: Value) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob):
            links = world.link_names(name) if isinstance(link, Var) else [link]
            yield from ((world, name, k, world.link_pose(name, k)) for k in links)

    return {
        "robot/2": robot,
        "joint_state/4": joint_state,
        "set_joint_state/4": set_joint_state,
        "link_pose/4": link_pose,
    }


def _attachments(world: PredicateWorld) -> dict[str, Implementation]:
    def attached(w: object, rob: object, link: object, obj: object) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob):
            for carried, at in world.bodies.attachments(name).items():
                yield (world, name, at, carried)

    def attach(w: object, obj: Value, rob: Value, link: Value) -> Solutions:
        if _ours(world, w):
            world.attach(obj, rob, link)
            yield None

    def detach(w: object, obj: Value) -> Solutions:
        if _ours(world, w):
            world.detach(obj)
            yield None

    return {"attached/4": attached, "attach/4": attach, "detach/2": detach}


def _reasoning(world: PredicateWorld) -> dict[str, Implementation]:
    def stable(w: object, obj: object) -> Solutions:
        if _ours(world, w):
            yield from ((world, n) for n in _names(world, obj) if world.physics.stable(n))

    def stable_all(w: object) -> Solutions:
        if _ours(world, w) and world.physics.stable():
            yield (world,)

    def visible(w: object, rob: object, obj: object) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob, robots_only=True):
            for seen in _names(world, obj):
                if seen != name and world.view.visible(name, seen):
                    yield (world, name, seen)

    def occluding_objects(w: object, rob: object, obj: object, occluders: object) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob, robots_only=True):
            for target in _names(world, obj):
                if target != name:
                    found = [o.name for o in world.view.occluding_objects(name, target)]
                    yield (world, name, target, found)

    return {
        "contact/3": _relation(world, world.contacts.contact),
        "supported_by/3": _relation(world, world.physics.supported_by),
        "above/3": _relation(world, world.physics.above),
        "below/3": _relation(world, world.physics.below),
        "stable/2": stable,
        "stable/1": stable_all,
        "visible/3": visible,
        "occluding_objects/4": occluding_objects,
    }
