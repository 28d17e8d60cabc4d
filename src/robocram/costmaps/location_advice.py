"""What to do when a location designator finds no pose, by what removed the candidates.

A costmap layer that left no cell and a validator that refused every candidate call for
different remedies: widening the search area does not help an object out of reach. The
tables say, per built-in cost function and validator, what the user can change; a user's
own function gets a text naming it. :class:`LocationNotFound` ends its message with this.
"""

from __future__ import annotations

from collections.abc import Mapping

GENERIC_ADVICE = "widen the search area, loosen the keys or clear the obstacles"
WIDE_ENOUGH = 5.0  # [m] a search square this wide holds every cell a camera (2.5 m range) or
# an arm could use round its target: widening it further cannot help, and is not advised
WIDEN = "widen `size`"  # the advice that holds only for a narrower search area

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
WIDE_LAYER_ADVICE: Mapping[str, str] = {  # the same where the search area is wide enough
    "behind": "no free cell behind the reference object: pick another relation or clear it",
    "in_front_of": "no free cell in front of the reference object: pick another relation "
    "or clear it",
    "left_of": "no free cell left of the reference object: pick another relation or clear it",
    "near": "no free cell near the reference object: clear its surroundings",
    "occupancy": "every cell round the target is blocked for the robot's footprint: clear "
    "the obstacles there (widening the search area cannot help: it holds every cell within "
    "the robot's reach), or give the robot a narrower footprint",
    "right_of": "no free cell right of the reference object: pick another relation or clear it",
    "visibility": "no cell within the camera's range (0.4 to 2.5 m) sees the target: remove "
    "what hides it, or check the camera's heights and range in the robot's description",
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


def layer_advice(layers: tuple[str, ...], area: float | None = None) -> str:
    """Why no cell had weight: the layers that zeroed the grid, with their remedies;
    ``area`` [m], the search square's side: from :data:`WIDE_ENOUGH` on, widening it is
    not advised (it would not help)."""
    if not layers:
        return GENERIC_ADVICE
    wide = area is not None and area >= WIDE_ENOUGH
    table = {**LAYER_ADVICE, **WIDE_LAYER_ADVICE} if wide else LAYER_ADVICE
    return "; ".join(
        f"the {name} layer left no cell: "
        + table.get(name, f"check what cost function {name!r} rules out")
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
    rejections: Mapping[str, int],
    accepted: int,
    in_a_row: int,
    emptied_by: tuple[str, ...],
    area: float | None = None,
) -> str:
    """The tail of a :class:`LocationNotFound` message: only the advice that applies."""
    if not rejections:
        return layer_advice(emptied_by, area)
    if accepted > 0:
        return (
            f"the stream ran dry after {accepted} accepted ({in_a_row} refused in a row): "
            + validator_advice(rejections)
        )
    return validator_advice(rejections)
