"""A look whose head stopped at its tilt limit above the target, judged by where the target
lies in the view.

Looking aims the camera's optical axis at the target; a pan-tilt head that cannot tilt
down so far (TALOS's stops 45 degrees down) turns to its limit and fails
(``PtuGoalNotReached``, ``below_tilt``). A target that lies little under the axis so turned
is in the view all the same: in the kitchen TALOS's camera, tilted to its limit at the
stands that reach the counter's mug, has it 3-8 degrees under its axis, a third of its
half field at most. Such a look counts as had; perception then judges what it sees, as
after any look. The scene's tabletop places TALOS's mug so too (``scenes/placement.py``,
``VIEW_EDGE_SHARE``).
"""

from __future__ import annotations

from robocram.execution.failures import PtuGoalNotReached

TILT_EDGE_SHARE = 0.5  # of the camera's half fields, off its axis, within which a target
# a head tilted down to its limit stopped above counts as looked at
VIEW_EDGE = 1.0  # of the same half fields: the view's edge


def seen_at_tilt_limit(failure: PtuGoalNotReached) -> bool:
    """Whether ``failure``'s head, stopped at its tilt limit above the target, has it in
    the view: under the axis by :data:`TILT_EDGE_SHARE` of the half field at most, and
    aside by no more (a head whose pan also stopped short may have it aside)."""
    if not failure.below_tilt or failure.view_share is None:
        return False
    aside, below = failure.view_share
    return 0.0 <= below <= TILT_EDGE_SHARE and abs(aside) <= TILT_EDGE_SHARE


def in_view_at_tilt_limit(failure: PtuGoalNotReached) -> bool:
    """Whether ``failure``'s head, stopped at its tilt limit above the target, has it in
    the view at all (within :data:`VIEW_EDGE` of the half fields): a look into an opened
    container at its middle then shows perception what lies in it, and perception judges
    that (TALOS, from where it opened the bowl's drawer, has the drawer's middle 0.81 of
    the half field under its axis, and sees the bowl)."""
    if not failure.below_tilt or failure.view_share is None:
        return False
    aside, below = failure.view_share
    return 0.0 <= below <= VIEW_EDGE and abs(aside) <= VIEW_EDGE
