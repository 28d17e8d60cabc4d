"""Name the stand-in box when a failed check involves a link whose mesh is missing.

A box sized from the kinematics is a guess: a palm box may reach into the object it
grips, a base box may touch a parked arm. When a failure names such a link, the card says
it is a stand-in and how to give the real mesh, so the user does not edit parking poses or
tool frames to work round a box.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import replace

from robocram.robot_check.report_card import CheckResult
from robocram.robots import RobotModel
from robocram.robots.stand_in_size import is_stand_in


def stand_in_links(model: RobotModel) -> dict[str, str]:
    """Link -> the missing mesh its collision box stands in for."""
    found: dict[str, str] = {}
    for link in model.links.values():
        for collision in link.collisions:
            if is_stand_in(collision.geometry):
                found.setdefault(link.name, collision.geometry.filename)
    return found


HAND_CHECKS = ("grip", "gripper", "tool frame", "reach")  # checks a hand's shape decides


def blame_stand_ins(
    model: RobotModel,
    results: Iterable[CheckResult],
    hands: Mapping[str, tuple[str, ...]] | None = None,
) -> list[CheckResult]:
    """``results`` with each failure naming a stand-in link told so, in its fix; a failed
    grip, gripper, tool frame or reach check of arm ``key`` also blames the stand-ins
    among ``hands[key]`` (its hand links)."""
    boxes = stand_in_links(model)
    out: list[CheckResult] = []
    for result in results:
        named = [link for link in boxes if _names(result.detail, link)]
        for key, links in (hands or {}).items():
            if result.name in {f"{key} arm: {check}" for check in HAND_CHECKS}:
                named += [link for link in links if link in boxes and link not in named]
        if result.passed or not named:
            out.append(result)
            continue
        listed = ", ".join(f"{link!r} (for {boxes[link]})" for link in named[:3])
        note = (
            f"{listed}: a box sized from the joints stands in for the missing mesh; give the "
            "meshes (`--package-path DIR`, ROS_PACKAGE_PATH, or the package beside the URDF)"
        )
        fix = f"{result.fix}; or {note}" if result.fix else note
        out.append(replace(result, fix=fix))
    return out


def _names(text: str, link: str) -> bool:
    return re.search(rf"(?<![\w]){re.escape(link)}(?![\w])", text) is not None
