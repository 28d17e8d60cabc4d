"""A palm hand: fingers side by side that curl one way, round what the palm faces.

A parallel gripper closes two jaws across a gap; a hand of three or more fingers lying
side by side (TIAGo's Hey5, Armar6's, Justin's, Alex's) has no such gap: its open fingers
form one row, and a thumb, if any, lies beside or behind it. Such a hand holds a body the
way a person holds a glass: the palm against it, the fingers curling round it. Taking the
row for a gripper's jaws put the middle finger into the mug from above, and reaching
sideways with the fingers first put the wrist beyond the arm's joint limits.

Read from the kinematics, in the tool frame, with the hand open:

- the fingers are the chains of gripper links; the one whose tip lies farthest from the
  others' tips is the thumb and is left out of the row;
- ``curl``: the way the fingertips start to move when the hand closes (across the
  fingers): the palm faces that way, and a grasp approaches along it;
- ``along``: from the knuckles to the tips: a grasp lays the fingers across the body;
- ``profile``: how far out along ``curl`` the row and the palm reach, per 5 mm along the
  fingers: where a body lies clear of them, against the palm.

A hand whose fingers curl different ways (a three-fingered gripper closing from around)
is no palm hand. Its fingers hold only what they reach half round (:attr:`Palm.wraps`):
round the mug's body the Hey5's met it on one side only; round its handle they close.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics import forward_kinematics
from robocram.robots import GripperDescription, RobotDescription, RobotModel
from robocram.robots.link_centre import link_points

PALM_GAP = 0.002  # [m] a held body's near side this far off the palm (within a grip's
# 5 mm, the palm counts as a side the body is squeezed from)
ROUND_BEHIND = 0.5  # a round body's middle this share of its half width behind the knuckles
FLAT_BEHIND = 1.1  # a flat face's middle this share of its half width behind them
FLAT = 0.02  # [m] a place this much higher than the lowest is the palm's heel
STEP = 0.005  # [m] places tried along the fingers, and the profile's step
BOX_CORNERS = 8  # a box's points: too few to fill a profile's steps
MIN_ROW = 3  # fingers besides the thumb: fewer are a gripper's jaws
CURL_PROBE = 0.95  # the hand this far open: where the tips start to curl
SAME_WAY = 0.5  # cos: each finger's curl this close to the row's
SWEEP = 11  # openings from closed to open the hand's sweep is read at (every 0.1)
Axis = tuple[float, float, float]


@dataclass(frozen=True)
class Palm:
    """How a palm hand holds, in its tool frame.

    Attributes:
        curl: unit, the way the fingers start to curl (the palm faces it).
        along: unit, the way the fingers point.
        knuckles: [m] the middle of the row's first links.
        reach: [m] from the knuckles to the row's far end, along ``along``.
        profile: [m] per link of the hand but the thumb's, ``(start, end, out)``: from
            where to where along ``along`` (from the knuckles) it lies, and how far out
            along ``curl`` it reaches.
        span: [m] how far the open hand (thumb too) reaches each way across the row
            (along ``curl`` x ``along``) from the knuckles: a grasp from the side keeps
            the lower end off the table.
        points: [m] the open hand's shapes' points (tool frame, thumb too): a handle
            taken from above must leave the body clear of them.
        swept: [m] the same shapes' points at :data:`SWEEP` openings from closed to open:
            where the hand passes as it closes (a rim grasp keeps them over the support).
    """

    curl: Axis
    along: Axis
    knuckles: Axis
    reach: float
    profile: tuple[tuple[float, float, float], ...]
    span: tuple[float, float]
    points: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 3)), compare=False)
    swept: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 3)), compare=False)

    def holding(self, half_width: float, depth: float, flat: bool) -> Axis:
        """The point [m, tool frame] a body ``half_width`` across the fingers is held at,
        ``depth`` [m] past its near side, which lies :data:`PALM_GAP` off the hand."""
        middle, out = self.place(half_width, flat)
        held = np.add(self.knuckles, np.multiply(middle, self.along))
        return _axis(held + np.multiply(out + PALM_GAP + depth, self.curl))

    @property
    def wraps(self) -> float:
        """The widest body [m] the fingers reach half round, past its far side: a palm hand
        holds by pressing it from there against the palm (the Hey5's 9 cm fingers curled
        a quarter round the 88 mm mug and met it on one side only; they close round its
        12 mm handle)."""
        return 2 * self.reach / math.pi

    @property
    def across(self) -> Axis:
        """The unit axis across the row: ``curl`` x ``along``."""
        return _axis(np.cross(self.curl, self.along))

    def height(self, middle: float, half_width: float, flat: bool) -> float:
        """How far out [m] along ``curl`` a body's near side must lie to clear the hand,
        its middle at ``middle`` [m along ``along``, from the knuckles]: a flat face
        clears what lies within ``half_width`` of it, a round side (a cylinder of radius
        ``half_width``) curves away from the hand off its middle."""
        found = 0.0
        for low, high, out in self.profile:
            off = max(low - middle, middle - high, 0.0)
            if off >= half_width:
                continue
            curve = 0.0 if flat else half_width - math.sqrt(half_width**2 - off**2)
            found = max(found, out - curve)
        return found

    def place(self, half_width: float, flat: bool) -> tuple[float, float]:
        """Where [m, from the knuckles] a body ``half_width`` across the fingers lies: its
        middle along the fingers, and how far out along ``curl`` its near side is.

        A round side (``flat`` False) lies :data:`ROUND_BEHIND` of its half width behind
        the knuckles, so that the fingers wrap past its far side, opposite the palm (with
        its middle at the knuckles they got 100 degrees round the mug and pressed on one
        side only); a flat face (a top) lies wholly behind them, the fingers curling down
        past its edge (over it, they curled into it). Where the palm there stands
        :data:`FLAT` higher than the lowest place, the body lies nearer the fingertips: a
        body kept off the fingers by the palm would not be held."""
        preferred = -half_width * (FLAT_BEHIND if flat else ROUND_BEHIND)
        steps = np.arange(preferred, self.reach + STEP, STEP).tolist()
        heights = [self.height(c, half_width, flat) for c in steps]
        lowest = min(heights)
        return next((c, h) for c, h in zip(steps, heights, strict=True) if h <= lowest + FLAT)


def _axis(v: np.ndarray) -> Axis:
    return (float(v[0]), float(v[1]), float(v[2]))


def _unit(v: np.ndarray) -> np.ndarray | None:
    norm = float(np.linalg.norm(v))
    return None if norm < 1e-9 else v / norm


def _chains(model: RobotModel, links: tuple[str, ...]) -> list[list[str]]:
    """The fingers: each a root gripper link (its parent no gripper link) and the gripper
    links below it, in file order."""
    members = set(links)
    parent = {j.child: j.parent for j in model.joints.values()}
    children: dict[str, list[str]] = {}
    for joint in model.joints.values():
        children.setdefault(joint.parent, []).append(joint.child)
    chains = []
    for root in (link for link in links if parent.get(link) not in members):
        chain, todo = [], [root]
        while todo:
            link = todo.pop()
            chain.append(link)
            todo += [c for c in children.get(link, []) if c in members]
        chains.append(chain)
    return chains


class _PosedHand:
    """Where the links of ``arm``'s hand lie in its tool frame as the hand opens."""

    def __init__(self, desc: RobotDescription, arm: str, gripper: GripperDescription) -> None:
        self.desc, self.spec, self.gripper = desc, desc.arms[arm], gripper
        self.tool = forward_kinematics(desc, {}, self.spec.tool_frame).inverse()

    def at(self, link: str, fraction: float = 1.0) -> np.ndarray:
        """The origin [m, tool frame] of ``link``, the hand ``fraction`` open."""
        pose = forward_kinematics(self.desc, self.gripper.at(fraction), link)
        return np.asarray((self.tool * pose).position)

    def ends(self, chain: list[str]) -> tuple[np.ndarray, str, np.ndarray]:
        """A finger's root, its tip link (the farthest from the root) and that tip, open."""
        root = self.at(chain[0])
        tip = max(chain, key=lambda link: float(np.linalg.norm(self.at(link) - root)))
        return root, tip, self.at(tip)

    def shapes(self, leave: set[str], fraction: float = 1.0) -> list[np.ndarray]:
        """Per link of the hand but those in ``leave``, its shapes' points [m, tool
        frame], the hand ``fraction`` open."""
        model = self.desc.model
        found = []
        for link in self.spec.hand_links:
            points = None if model is None or link in leave else link_points(model.link(link))
            if points is not None:
                pose = (
                    self.tool * forward_kinematics(self.desc, self.gripper.at(fraction), link)
                ).matrix()
                found.append(points @ pose[:3, :3].T + pose[:3, 3])
        return found


def palm_of(desc: RobotDescription, arm: str) -> Palm | None:
    """The palm of ``arm``'s hand (tool frame), or None when it is no palm hand."""
    gripper = desc.arms[arm].gripper
    if desc.model is None or gripper is None or gripper.is_suction or not gripper.joints:
        return None
    chains = _chains(desc.model, tuple(desc.arms[arm].gripper_links))
    if len(chains) < MIN_ROW + 1:
        return None
    hand = _PosedHand(desc, arm, gripper)
    ends = [hand.ends(chain) for chain in chains]
    tips = np.asarray([tip for _, _, tip in ends])
    thumb = max(
        range(len(chains)),
        key=lambda k: float(np.linalg.norm(tips[k] - np.delete(tips, k, 0).mean(axis=0))),
    )
    row = [e for k, e in enumerate(ends) if k != thumb]
    along = _unit(np.mean([tip - root for root, _, tip in row], axis=0))
    curl = None if along is None else _curl(hand, row, along)
    if along is None or curl is None:
        return None
    knuckles = np.mean([root for root, _, _ in row], axis=0)
    profile = tuple(
        part
        for points in hand.shapes(set(chains[thumb]))
        for part in _parts((points - knuckles) @ along, (points - knuckles) @ curl)
    )
    if not profile:
        return None
    shapes = np.vstack(hand.shapes(set()))
    sideways = (shapes - knuckles) @ np.cross(curl, along)
    span = (float(sideways.min()), float(sideways.max()))
    reach = max(end for _, end, _ in profile)
    swept = np.vstack([p for f in np.linspace(0.0, 1.0, SWEEP) for p in hand.shapes(set(), f)])
    return Palm(_axis(curl), _axis(along), _axis(knuckles), reach, profile, span, shapes, swept)


def _curl(
    hand: _PosedHand, row: list[tuple[np.ndarray, str, np.ndarray]], along: np.ndarray
) -> np.ndarray | None:
    """The way the row's tips start to move across the fingers as the hand closes (unit),
    or None when they do not move one way."""
    curls = []
    for _, tip, at in row:
        moved = hand.at(tip, CURL_PROBE) - at
        across = _unit(moved - float(moved @ along) * along)
        if across is None:
            return None
        curls.append(across)
    curl = _unit(np.mean(curls, axis=0))
    if curl is None or min(float(c @ curl) for c in curls) < SAME_WAY:
        return None
    return curl


def _parts(ahead: np.ndarray, out: np.ndarray) -> list[tuple[float, float, float]]:
    """One link's profile: per :data:`STEP` along the fingers, how far out it reaches; a
    box's eight corners (too few points to fill the steps between) as one part."""
    if len(ahead) <= BOX_CORNERS:
        return [(float(ahead.min()), float(ahead.max()), float(out.max()))]
    bins = np.floor(ahead / STEP).astype(int)
    return [
        (float(k * STEP), float((k + 1) * STEP), float(out[bins == k].max()))
        for k in np.unique(bins).tolist()
    ]
