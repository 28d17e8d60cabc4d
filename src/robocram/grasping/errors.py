"""Errors of the grasp model: one root, and the object no grasp of a hand fits."""

from __future__ import annotations

import math


class GraspingError(Exception):
    """Root of the grasp model's errors."""


class ObjectUngraspable(GraspingError, ValueError):
    """No grasp of the object fits the hand: every one needs a wider opening.

    Attributes:
        object: the object's name.
        hand_width: [m] the hand's widest opening.
        needed_width: [m] the narrowest opening any grasp of the object needs.
    """

    def __init__(self, object: str, hand_width: float, needed_width: float) -> None:  # noqa: A002
        self.object = object
        self.hand_width = hand_width
        self.needed_width = needed_width
        super().__init__(
            f"no grasp of {object!r} fits a hand opening {hand_width:.3f} m: the narrowest "
            f"grasp needs {needed_width:.3f} m; use a robot with a wider hand, or declare a "
            "narrower part to hold (object_handle/2, object_wall/2 facts)"
        )


class UnknownGraspError(GraspingError, ValueError):
    """A grasp name the model does not know."""

    def __init__(self, name: str, known: tuple[str, ...]) -> None:
        self.name = name
        self.known = known
        super().__init__(f"unknown grasp {name!r}; grasps: {', '.join(known)}")


class ObjectUntouchable(ObjectUngraspable):
    """No face of the object a suction hand may touch among the grasps allowed."""

    def __init__(self, object: str, allowed: tuple[str, ...]) -> None:  # noqa: A002
        self.object = object
        self.hand_width = 0.0
        self.needed_width = math.inf
        self.allowed = allowed
        GraspingError.__init__(
            self,
            f"a suction hand holds {object!r} only by a face (top, rim if hollow, side), and "
            f"its grasps allow {', '.join(allowed) or 'none'}: allow 'top', 'rim' or 'side' "
            "(object_grasps/2), or use a hand with fingers",
        )
