"""The turtle's action plans: navigating, and drawing a house as navigation actions.

Plans only PERFORM designators, so they run unchanged in any turtle environment.
"""

from __future__ import annotations

from collections.abc import Sequence

from robocram.designators import a, an
from robocram.execution.perform import perform
from robocram.turtlesim.errors import TurtleArgumentError
from robocram.turtlesim.world import Point, TurtlePose


def navigate(goal: object) -> TurtlePose:
    """Go to ``goal`` (a point or a location designator) by a ``moving`` motion."""
    pose: TurtlePose = perform(a.motion(type="moving", goal=goal))
    return pose


def house_corners(origin: Sequence[float], size: float) -> list[Point]:
    """Return the corners of "das Haus vom Nikolaus", in drawing order: 8 strokes, one path.

    The square's lower left corner is ``origin`` [m], its side ``size`` [m]; the roof's
    apex is ``size / 2`` above the square.
    """
    if len(origin) != 2 or size <= 0:
        raise TurtleArgumentError(
            f"a house needs an origin (x, y) and a size > 0, got {origin}, {size}"
        )
    x, y, s = float(origin[0]), float(origin[1]), float(size)
    bottom_left, bottom_right = (x, y), (x + s, y)
    top_left, top_right, apex = (x, y + s), (x + s, y + s), (x + s / 2, y + 1.5 * s)
    return [
        bottom_left,
        bottom_right,
        top_left,
        top_right,
        apex,
        top_left,
        bottom_left,
        top_right,
        bottom_right,
    ]


def draw_house(origin: Sequence[float], size: float) -> list[TurtlePose]:
    """Draw the house: pen up to the first corner, pen down, navigate corner to corner."""
    corners = house_corners(origin, size)
    perform(a.motion(type="setting-pen", pen="up"))
    reached = [perform(an.action(type="navigating", target=corners[0]))]
    perform(a.motion(type="setting-pen", pen="down"))
    reached += [perform(an.action(type="navigating", target=c)) for c in corners[1:]]
    perform(a.motion(type="setting-pen", pen="up"))
    return reached
