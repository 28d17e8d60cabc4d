"""A hand whose fingers are drawn but given no collision shape takes its drawing as shape.

Some URDFs leave collision shapes out where they are awkward: the SO-100's fixed and
moving jaws (``gripper``, ``jaw``) carry only their visual meshes, so its fingers passed
through every object and the check measured them 0 m apart. Fingers without shapes hold
nothing, and their visual meshes are the best word on where their bodies are, so at a
hand (the wrist link and every link below it) none of whose fingers (the links a joint
below the wrist moves) has a collision shape, each link with visuals but no collision
gets those as its collision shapes (a mesh collides as its convex hull, as every moving
link's does). A hand whose fingers have shapes is left as it is (a PR2's wrist roll and
accelerometer links are drawn only), and so is every link elsewhere.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace

from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Collision, Link


def with_hand_shapes(model: RobotModel, wrists: Iterable[str]) -> RobotModel:
    """``model`` with each shapeless link at the hands below ``wrists`` given its visuals as
    collision shapes; ``model`` itself when no link needs them.

    The result is kept with ``model`` (``RobotModel.derived``), so loads share one model."""
    key = tuple(sorted(set(wrists)))
    kept = model.derived(_shaped_models)
    if key not in kept:
        shaped = _shaped(model, key)
        if shaped is not model:
            shaped.derived(ShapedFrom).source = model
        kept[key] = shaped
    return kept[key]


def shapeless_hand_links(model: RobotModel, wrists: Iterable[str]) -> list[str]:
    """The drawn links without a collision shape at the hands below ``wrists`` whose
    fingers have no collision shape; in file order of the joints, hand by hand."""
    found: list[str] = []
    for wrist in dict.fromkeys(wrists):
        if wrist not in model.links:
            continue
        hand = _below(model, wrist)
        fingers = [link for link, moved in hand.items() if moved]
        if not fingers or any(model.links[link].collisions for link in fingers):
            continue
        found += [k for k in hand if model.links[k].visuals and not model.links[k].collisions]
    return list(dict.fromkeys(found))


def _below(model: RobotModel, wrist: str) -> dict[str, bool]:
    """``wrist`` and every link below it, each with whether a movable joint below the wrist
    moves it (a finger)."""
    found = {wrist: False}
    queue = [wrist]
    while queue:
        parent = queue.pop(0)
        for joint in model.joints.values():
            if joint.parent == parent and joint.child not in found:
                found[joint.child] = found[parent] or joint.movable
                queue.append(joint.child)
    return found


class ShapedFrom:
    """The model a shaped model was made from, held by the shaped one (as
    ``grasp_space.CutFrom``): the model memo holds the parse only weakly."""

    def __init__(self, shaped: RobotModel) -> None:
        self.source: RobotModel | None = None


def _shaped_models(model: RobotModel) -> dict[tuple[str, ...], RobotModel]:
    """The shaped models made from ``model``, by the wrists they were made for."""
    return {}


def _shaped(model: RobotModel, wrists: tuple[str, ...]) -> RobotModel:
    names = shapeless_hand_links(model, wrists)
    if not names:
        return model
    links = dict(model.links)
    for name in names:
        links[name] = _drawn_as_shape(links[name])
    return RobotModel(model.name, links, model.joints, model.source)


def _drawn_as_shape(link: Link) -> Link:
    shapes = tuple(Collision(v.geometry, v.origin, v.name) for v in link.visuals)
    return replace(link, collisions=shapes)
