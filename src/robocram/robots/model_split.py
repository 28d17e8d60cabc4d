"""Cut a model too big for one physics body into parts at articulated subtrees.

PyBullet holds at most 127 links below a body's root (and sets at most 121 moving joints).
A kitchen of 135 links is mostly cabinets hung on fixed joints, each with its drawers and
doors: such a subtree, rigid with the root, can be its own fixed body placed where it
hangs, and every link, joint and shape keeps its name. Only fixed joints whose whole path
from the root is fixed are cut, so a part never moves against the rest.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Joint
from robocram.tf import Pose


@dataclass(frozen=True)
class ModelPart:
    """One part of a cut model: its links and joints, and where its root link lies.

    ``root_T_base``: the part's root link (the cut joint's child) in the whole model's
    root frame; ``cut``: the fixed joint that was cut, so the part hangs there.
    """

    model: RobotModel
    root_T_base: Pose
    cut: str


@dataclass(frozen=True)
class SplitModel:
    """The model's root part (``main``) and the subtrees cut off it, biggest first."""

    main: RobotModel
    parts: tuple[ModelPart, ...]


def split_model(model: RobotModel, max_links: int, max_moving: int) -> SplitModel:
    """``model`` cut into parts of at most ``max_links`` links below each part's root and
    ``max_moving`` moving joints; a model that fits is one part (``parts`` empty).

    Subtrees holding moving joints are cut first, the biggest that fits first. Where no
    more subtree can be cut the main part stays too big: the caller refuses it.
    """
    children: dict[str, list[Joint]] = {}
    for joint in model.joints.values():
        children.setdefault(joint.parent, []).append(joint)
    sizes = _subtree_sizes(model, children)
    rigid = _rigid_with_root(model, children)
    candidates = sorted(
        (j for j in model.joints.values() if j.type == "fixed" and j.parent in rigid),
        key=lambda j: (sizes[j.child][1] > 0, sizes[j.child][0]),
        reverse=True,
    )
    links, moving = len(model.joints), len(model.movable_joints())
    cut: list[Joint] = []
    taken: set[str] = set()
    for joint in candidates:
        if links <= max_links and moving <= max_moving:
            break
        size, moves = sizes[joint.child]
        if size - 1 > max_links or moves > max_moving or joint.child in taken:
            continue
        if _holds_cut(joint.child, cut, model):
            continue
        cut.append(joint)
        taken |= _subtree(joint.child, children)
        links, moving = links - size, moving - moves
    if not cut:
        return SplitModel(model, ())
    parts = tuple(_part(model, joint, children) for joint in cut)
    main_links = {n: link for n, link in model.links.items() if n not in taken}
    main_joints = {n: j for n, j in model.joints.items() if j.child not in taken}
    return SplitModel(RobotModel(model.name, main_links, main_joints, model.source), parts)


def _subtree_sizes(
    model: RobotModel, children: dict[str, list[Joint]]
) -> dict[str, tuple[int, int]]:
    """Per link: the links in its subtree (itself included) and the moving joints in it."""
    order: list[str] = []
    todo = [model.root_link]
    while todo:
        link = todo.pop()
        order.append(link)
        todo.extend(j.child for j in children.get(link, []))
    sizes: dict[str, tuple[int, int]] = {}
    for link in reversed(order):
        below = [(sizes[j.child], j.movable) for j in children.get(link, [])]
        sizes[link] = (
            1 + sum(s[0] for s, _ in below),
            sum(s[1] + int(movable) for s, movable in below),
        )
    return sizes


def _rigid_with_root(model: RobotModel, children: dict[str, list[Joint]]) -> set[str]:
    """The links joined to the root by fixed joints only."""
    rigid = {model.root_link}
    todo = [model.root_link]
    while todo:
        for joint in children.get(todo.pop(), []):
            if joint.type == "fixed":
                rigid.add(joint.child)
                todo.append(joint.child)
    return rigid


def _subtree(link: str, children: dict[str, list[Joint]]) -> set[str]:
    found = {link}
    todo = [link]
    while todo:
        for joint in children.get(todo.pop(), []):
            found.add(joint.child)
            todo.append(joint.child)
    return found


def _holds_cut(link: str, cut: list[Joint], model: RobotModel) -> bool:
    """Whether a joint already cut lies below ``link`` (its part would hold that part)."""
    for joint in cut:
        above = joint.parent
        while True:
            if above == link:
                return True
            parent = model.parent_joint(above)
            if parent is None:
                break
            above = parent.parent
    return False


def _part(model: RobotModel, joint: Joint, children: dict[str, list[Joint]]) -> ModelPart:
    links = _subtree(joint.child, children)
    part_links = {n: link for n, link in model.links.items() if n in links}
    part_joints = {n: j for n, j in model.joints.items() if j.child in links and n != joint.name}
    where = joint.origin
    above = joint.parent
    while (parent := model.parent_joint(above)) is not None:
        where = parent.origin * where
        above = parent.parent
    part = RobotModel(f"{model.name}__{joint.child}", part_links, part_joints, model.source)
    return ModelPart(part, where, joint.name)
