"""Where a one-sided jaw holds an object: the middle of the opening between its jaws.

A jaw turning against a jaw fixed to the wrist (Unitree's Z1, the SO-101) closes an object
against the fixed jaw's inner face. A tool frame at the closed jaw's middle lies inside
the fixed jaw, so an object put there is pushed by the moving jaw against nothing. The
tool frame goes to the middle of the opening instead: between the fixed jaw's inner face
and the moving jaw's grip face standing open, so a grip there closes the object against
the fixed jaw. Measured on the links' collision shapes (a mesh's vertices: a box round a
jaw and its housing hides the face), in the wrist link:

- the grip zone: along the approach, the outer half of the moving jaw closed, and across,
  its width;
- the fixed jaw's inner face: its points in the zone farthest towards the opening;
- the open face: the moving jaw's points in the zone nearest the fixed jaw with the jaw
  open, or the middle of its shape where opening swings it out of the zone.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

import numpy as np

from robocram.robots.draft.hands import Hand
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.link_centre import link_points


def shape_points(
    tree: ModelTree, links: Iterable[str], values: Mapping[str, float], wrist_link: str
) -> np.ndarray:
    """Points [m, wrist link, N x 3] on the shapes of ``links`` with the joints at ``values``."""
    poses = link_poses(tree.model, dict(values))
    wrist = poses[wrist_link].inverse()
    found = []
    for link in links:
        points = link_points(tree.model.link(link))
        if points is None:
            continue
        matrix = (wrist * poses[link]).matrix()
        found.append(points @ matrix[:3, :3].T + matrix[:3, 3])
    return np.vstack(found) if found else np.empty((0, 3))


def _zone(
    points: np.ndarray, approach: np.ndarray, across: np.ndarray, bounds: np.ndarray
) -> np.ndarray:
    """The rows of ``points`` inside the grip zone ``bounds`` (approach low/high, across
    low/high)."""
    a, c = points @ approach, points @ across
    inside = (a >= bounds[0]) & (a <= bounds[1]) & (c >= bounds[2]) & (c <= bounds[3])
    return points[inside]


def jaw_opening_centre(
    tree: ModelTree,
    hand: Hand,
    directions: tuple[np.ndarray, np.ndarray],
    closed: Mapping[str, float],
    opened: Mapping[str, float],
) -> np.ndarray | None:
    """The middle [m, wrist link] of a one-sided jaw's opening, or None where the shapes
    show no fixed jaw facing the moving one. ``directions``: the unit approach, and the
    opening pointing the way the moving jaw opens (away from the fixed jaw)."""
    approach, opening = directions
    across = np.cross(approach, opening)
    wrist, movers = hand.end_effector_link, tuple(hand.gripper_links)
    fixed = (wrist, *(link for link in hand.hand_links if link not in movers))
    shut = shape_points(tree, movers, closed, wrist)
    if not len(shut):
        return None
    reach, width = shut @ approach, shut @ across
    bounds = np.array(
        ((reach.min() + reach.max()) / 2, reach.max(), width.min(), width.max()), float
    )
    jaw = _zone(shape_points(tree, fixed, closed, wrist), approach, across, bounds)
    jaw = jaw[jaw @ opening <= float(np.max(shut @ opening))]  # below the moving jaw's top
    if not len(jaw):
        return None
    face = float(np.max(jaw @ opening))
    wide = shape_points(tree, movers, opened, wrist)
    standing = _zone(wide, approach, across, bounds)
    if len(standing):
        far = float(np.min(standing @ opening))
    else:
        far = float(((wide.min(axis=0) + wide.max(axis=0)) / 2) @ opening)
    if far <= face:
        return None
    along = (bounds[0] + bounds[1]) / 2 * approach
    return along + (face + far) / 2 * opening + (bounds[2] + bounds[3]) / 2 * across
