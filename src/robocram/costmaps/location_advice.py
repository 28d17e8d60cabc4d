"""What to do when a location designator finds no pose, by what removed the candidates.

A costmap layer that left no cell and a validator that refused every candidate call for
different remedies: widening the search area does not help an object out of reach. The
tables say, per built-in cost function and validator, what the user can change; a user's
own function gets a text naming it. :class:`LocationNotFound` ends its message with this.
"""

from __future__ import annotations

from collections.abc import Mapping

GENERIC_ADVICE = "widen the search area, loosen the keys or clear the obstacles"

_SIDE = "no cell {} the reference object lies in the search area: widen `size` or pick another"
LAYER_ADVICE: Mapping[str, str] = {
    "at": "the point lies outside the search area or off the other keys' cells: move it",
    "behind": _SIDE.format("behind"),
    "in_front_of": _SIDE.format("in front of"),
    "inside": "the container has no free floor: empty it or choose another container",
    "left_of": _SIDE.format("left of"),
    "near": "no cell near the reference object lies in the search area: widen `size`",
    "occupancy": "every cell within reach is blocked: clear the obstacles or widen `size`",
    "on": "the surface has no free spot: clear it or choose another surface",
    "reachability": "the object is beyond the robot's reach from every cell searched: "
    "move it or use another arm/robot",
    "right_of": _SIDE.format("right of"),
    "visibility": "no cell within the camera's range (0.4 to 2.5 m) sees the target: "
    "remove what hides it, or widen `size` if the search area is smaller than that",
}

VALIDATOR_ADVICE: Mapping[str, str] = {
    "object_collision_free": "the object touches something at each place: clear the "
    "surface or choose another",
    "reachable": "no grasp the pick would try works from these stands: try another grasp "
    "or arm, or move the object",
    "robot_collision_free": "the robot (or what it holds) touches something at each stand: "
    "clear the area",
    "visible": "the aimed camera sees too little of the target from each stand: remove "
    "what hides it or move it",
}


def layer_advice(layers: tuple[str, ...]) -> str:
    """Why no cell had weight: the layers that zeroed the grid, with their remedies."""
    if not layers:
        return GENERIC_ADVICE
    return "; ".join(
        f"the {name} layer left no cell: "
        + LAYER_ADVICE.get(name, f"check what cost function {name!r} rules out")
        for name in layers
    )


def validator_advice(rejections: Mapping[str, int]) -> str:
    """Why the candidates were refused: each validator, most rejections first, its remedy."""
    ranked = sorted(rejections.items(), key=lambda item: (-item[1], item[0]))
    return "; ".join(
        f"{name} ({count}): "
        + VALIDATOR_ADVICE.get(name, f"validator {name!r} refused them: check what it tests")
        for name, count in ranked
    )


def not_found_advice(
    rejections: Mapping[str, int], accepted: int, in_a_row: int, emptied_by: tuple[str, ...]
) -> str:
    """The tail of a :class:`LocationNotFound` message: only the advice that applies."""
    if not rejections:
        return layer_advice(emptied_by)
    if accepted > 0:
        return (
            f"the stream ran dry after {accepted} accepted ({in_a_row} refused in a row): "
            + validator_advice(rejections)
        )
    return validator_advice(rejections)
