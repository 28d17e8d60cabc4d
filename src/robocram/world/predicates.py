"""The world as predicates of its own knowledge base.

Every predicate takes the world first (``W``, bound by ``world(W)``); objects, robots,
links and joints are name atoms. Unbound names enumerate. Predicates that change the
world (``set_joint_state``, ``set_object_pose``, ``attach``, ``detach``, ``simulate``)
succeed once; CRAM's ``assert`` forms are named so as not to clash with Prolog's own.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

from robocram.logic import KnowledgeBase, Var
from robocram.logic.limits import current_stop_check
from robocram.tf import Pose

if TYPE_CHECKING:
    from robocram.world.world import World

Solutions = Iterator[tuple[Any, ...] | None]


def world_knowledge_base(world: World) -> KnowledgeBase:
    """A new knowledge base with the predicates of ``world``."""
    kb = KnowledgeBase()
    for install in (_install_objects, _install_robots, _install_attachments, _install_reasoning):
        install(kb, world)
    return kb


def _names(world: World, arg: Any, robots_only: bool = False) -> list[str]:
    """The object names ``arg`` may stand for: all when unbound, else itself if it exists."""
    pool = world.robots() if robots_only else world.objects()
    if isinstance(arg, Var):
        return [o.name for o in pool]
    return [o.name for o in pool if o.name == arg]


def _ours(world: World, arg: Any) -> bool:
    return isinstance(arg, Var) or arg is world


def _relation(world: World, test: Callable[[str, str], bool]) -> Callable[..., Solutions]:
    """A predicate ``p(W, A, B)`` enumerating the pairs of distinct objects for which
    ``test`` holds."""

    def solve(w: Any, a: Any, b: Any) -> Solutions:
        if not _ours(world, w):
            return
        for name_a in _names(world, a):
            for name_b in _names(world, b):
                if name_a != name_b and test(name_a, name_b):
                    yield (world, name_a, name_b)

    return solve


def _install_objects(kb: KnowledgeBase, world: World) -> None:
    @kb.predicate("world", 1)
    def world_(w: Any) -> Solutions:
        if _ours(world, w):
            yield (world,)

    @kb.predicate("object", 2)
    def object_(w: Any, name: Any) -> Solutions:
        if _ours(world, w):
            yield from ((world, n) for n in _names(world, name))

    @kb.predicate("object_type", 3)
    def object_type(w: Any, name: Any, kind: Any) -> Solutions:
        if _ours(world, w):
            yield from ((world, n, world.object(n).type) for n in _names(world, name))

    @kb.predicate("object_pose", 3)
    def object_pose(w: Any, name: Any, pose: Any) -> Solutions:
        if _ours(world, w):
            yield from ((world, n, world.pose(n)) for n in _names(world, name))

    @kb.predicate("set_object_pose", 3)
    def set_object_pose(w: Any, name: Any, pose: Any) -> Solutions:
        if _ours(world, w) and not isinstance(name, Var):
            world.set_pose(name, Pose.coerce(_pose_value(pose)))
            yield None

    @kb.predicate("simulate", 2)
    def simulate(w: Any, seconds: Any) -> Solutions:
        if _ours(world, w):
            world.simulate(float(seconds), stop_check=current_stop_check())  # a task's stop
            yield (world, seconds)


def _pose_value(value: Any) -> Any:
    """A pose given as a Pose or as Prolog lists ``[[X, Y, Z], [QX, QY, QZ, QW]]``."""
    if isinstance(value, list) and len(value) == 2 and isinstance(value[0], list):
        return (tuple(value[0]), tuple(value[1]))
    if isinstance(value, list):
        return tuple(value)
    return value


def _install_robots(kb: KnowledgeBase, world: World) -> None:
    @kb.predicate("robot", 2)
    def robot(w: Any, name: Any) -> Solutions:
        if _ours(world, w):
            yield from ((world, n) for n in _names(world, name, robots_only=True))

    @kb.predicate("joint_state", 4)
    def joint_state(w: Any, rob: Any, joint: Any, value: Any) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob, robots_only=True):
            states = world.joint_states(name)
            joints = list(states) if isinstance(joint, Var) else [joint]
            yield from ((world, name, j, states[j]) for j in joints if j in states)

    @kb.predicate("set_joint_state", 4)
    def set_joint_state(w: Any, rob: Any, joint: Any, value: Any) -> Solutions:
        if _ours(world, w):
            world.set_joint_states(rob, {joint: float(value)})
            yield None

    @kb.predicate("link_pose", 4)
    def link_pose(w: Any, rob: Any, link: Any, pose: Any) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob):
            links = world.link_names(name) if isinstance(link, Var) else [link]
            yield from ((world, name, k, world.link_pose(name, k)) for k in links)


def _install_attachments(kb: KnowledgeBase, world: World) -> None:
    @kb.predicate("attached", 4)
    def attached(w: Any, rob: Any, link: Any, obj: Any) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob):
            for carried, at in world.attachments(name).items():
                yield (world, name, at, carried)

    @kb.predicate("attach", 4)
    def attach(w: Any, obj: Any, rob: Any, link: Any) -> Solutions:
        if _ours(world, w):
            world.attach(obj, rob, link)
            yield None

    @kb.predicate("detach", 2)
    def detach(w: Any, obj: Any) -> Solutions:
        if _ours(world, w):
            world.detach(obj)
            yield None


def _install_reasoning(kb: KnowledgeBase, world: World) -> None:
    kb.predicate("contact", 3)(_relation(world, world.contact))
    kb.predicate("supported_by", 3)(_relation(world, world.supported_by))
    kb.predicate("above", 3)(_relation(world, world.above))
    kb.predicate("below", 3)(_relation(world, world.below))

    @kb.predicate("stable", 2)
    def stable(w: Any, obj: Any) -> Solutions:
        if _ours(world, w):
            yield from ((world, n) for n in _names(world, obj) if world.stable(n))

    @kb.predicate("stable", 1)
    def stable_all(w: Any) -> Solutions:
        if _ours(world, w) and world.stable():
            yield (world,)

    @kb.predicate("visible", 3)
    def visible(w: Any, rob: Any, obj: Any) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob, robots_only=True):
            for seen in _names(world, obj):
                if seen != name and world.visible(name, seen):
                    yield (world, name, seen)

    @kb.predicate("occluding_objects", 4)
    def occluding_objects(w: Any, rob: Any, obj: Any, occluders: Any) -> Solutions:
        if not _ours(world, w):
            return
        for name in _names(world, rob, robots_only=True):
            for target in _names(world, obj):
                if target != name:
                    found = [o.name for o in world.occluding_objects(name, target)]
                    yield (world, name, target, found)
