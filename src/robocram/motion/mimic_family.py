"""A joint and the joints that mimic it: what moves when a planned joint moves.

A motion plans only master joints; their URDF ``<mimic>`` followers move with them (the
HSR's head rises on ``torso_lift_joint``, half of ``arm_lift_joint``; the PR2's right
finger follows its left). Whatever checks or bounds a motion must see the followers'
links move too.
"""

from __future__ import annotations

from robocram.robots import RobotModel


def mimic_family(model: RobotModel, name: str) -> list[tuple[str, float, float]]:
    """``(joint, multiplier, offset)`` of ``name`` itself and every joint mimicking it,
    transitively: a follower's value is ``multiplier * value(name) + offset``."""
    mimics = model.derived(_mimics)
    found = [(name, 1.0, 0.0)]
    k = 0
    while k < len(found):
        master, mult, off = found[k]
        for joint, multiplier, offset in mimics.get(master, ()):
            found.append((joint, multiplier * mult, multiplier * off + offset))
        k += 1
    return found


def _mimics(model: RobotModel) -> dict[str, list[tuple[str, float, float]]]:
    """Per master joint: ``(joint, multiplier, offset)`` of the joints mimicking it
    directly, in the model's order (kept with the model: a checker is made per motion,
    and scanning every joint per planned joint cost more than the rest of its slots)."""
    found: dict[str, list[tuple[str, float, float]]] = {}
    for joint in model.joints.values():
        if joint.mimic is not None:
            m = joint.mimic
            found.setdefault(m.joint, []).append((joint.name, m.multiplier, m.offset))
    return found
