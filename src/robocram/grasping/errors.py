"""Errors of the grasp model: one root, and the object no grasp of a hand fits."""

from __future__ import annotations


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
