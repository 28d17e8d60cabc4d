"""Which of a robot's links are adjacent: pairs a self-collision audit does not judge.

Computed here from the URDF, apart from the planner's own rules: links joined by fixed
joints are one rigid group; two groups are adjacent when one movable joint joins them, or
when the only groups between them have no collision geometry (those are looked through,
as MoveIt's setup assistant does: the PR2's upper-arm roll link has no shape, so the
shoulder lift link and the upper arm meet at their joint). Pairs within one group are
adjacent too. Only links with collision geometry are named.
"""

from __future__ import annotations

import itertools
from collections import deque

from robocram.robots import RobotModel

LinkPair = frozenset[str]  # two link names, in no order


def adjacent_links(model: RobotModel) -> frozenset[LinkPair]:
    """The pairs of ``model``'s links with collision geometry that are adjacent."""
    group = _rigid_groups(model)
    members: dict[str, list[str]] = {}
    for link, top in group.items():
        if model.links[link].collisions:
            members.setdefault(top, []).append(link)
    neighbours: dict[str, set[str]] = {top: set() for top in set(group.values())}
    for joint in model.joints.values():
        if joint.type != "fixed":
            a, b = group[joint.parent], group[joint.child]
            neighbours[a].add(b)
            neighbours[b].add(a)
    pairs: set[LinkPair] = set()
    for links in members.values():
        pairs.update(frozenset(p) for p in itertools.combinations(links, 2))
    for top, links in members.items():
        for other in _seen_through_empty(top, neighbours, members):
            pairs.update(frozenset((a, b)) for a in links for b in members[other])
    return frozenset(pairs)


def _rigid_groups(model: RobotModel) -> dict[str, str]:
    """Each link's group: the top link of the fixed joints above it."""
    group: dict[str, str] = {}
    for link in model.links:
        top = link
        joint = model.parent_joint(top)
        while joint is not None and joint.type == "fixed":
            top = joint.parent
            joint = model.parent_joint(top)
        group[link] = top
    return group


def _seen_through_empty(
    start: str, neighbours: dict[str, set[str]], members: dict[str, list[str]]
) -> set[str]:
    """Groups with geometry one movable joint from ``start``, or beyond groups without."""
    found: set[str] = set()
    visited = {start}
    queue = deque(neighbours[start])
    while queue:
        top = queue.popleft()
        if top in visited:
            continue
        visited.add(top)
        if top in members:
            found.add(top)
        else:
            queue.extend(neighbours[top])
    return found
