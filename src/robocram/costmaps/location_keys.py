"""Designator keys to costmap layers and validators, by the rules of ``location_keys.pl``.

The rules live in the knowledge base as fact group ``location_costmaps``, so a user adds a
key with one clause (``location_cost(under, under_cost).``) in a group of their own and
one Python function registered under that name; the library is not edited.
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import resources
from typing import Any

from robocram.costmaps.errors import LocationKeyError
from robocram.designators import Designator
from robocram.logic import KnowledgeBase

GROUP = "location_costmaps"
EXTENDABLE = (
    "location_cost/2",
    "location_robot_key/1",
    "location_option/1",
    "location_conflict/2",
    "location_validator/2",
)


def install_location_keys(kb: KnowledgeBase) -> None:
    """Load the key rules into ``kb`` as fact group ``location_costmaps`` (idempotent)."""
    text = resources.files("robocram.costmaps").joinpath("location_keys.pl").read_text("utf-8")
    kb.consult(text, group=GROUP, extendable=EXTENDABLE)


@dataclass(frozen=True)
class LocationPlan:
    """What the rules make of one designator: its layers, validators and robot key."""

    cost_functions: tuple[tuple[str, str], ...]  # (key, cost function name), in order
    validators: tuple[str, ...]
    robot_key: str | None

    @property
    def empty(self) -> bool:
        """Whether no key of the designator asks for a costmap."""
        return not self.cost_functions


def _all(kb: KnowledgeBase, goal: str, var: str, **bindings: Any) -> list[Any]:
    return [answer[var] for answer in kb.query(goal, **bindings)]


def _check_keys(kb: KnowledgeBase, designator: Designator[object], keys: list[str]) -> None:
    known = set(_all(kb, "location_cost(K, _)", "K")) | set(_all(kb, "location_option(K)", "K"))
    for key in keys:
        if key not in known:
            raise LocationKeyError(
                f"{designator.description}: no rule knows the location key {key!r} "
                f"(known: {', '.join(sorted(known))}); add one with a location_cost/2 "
                "clause and a cost function, or fix the key",
                key,
                designator,
            )
    for a in keys:
        for b in _all(kb, "location_conflict(A, B)", "B", A=a):
            if b in keys:
                raise LocationKeyError(
                    f"{designator.description}: keys {a!r} and {b!r} exclude each other; "
                    "use one of them",
                    b,
                    designator,
                )


def plan_location(kb: KnowledgeBase, designator: Any) -> LocationPlan:
    """The layers and validators the rules give ``designator``'s keys.

    Raises:
        LocationKeyError: a key no rule knows, or two keys that exclude each other.
    """
    keys = list(dict.fromkeys(k for k, _ in designator.properties))
    _check_keys(kb, designator, keys)
    layers: list[tuple[str, str]] = []
    validators: list[str] = []
    robot_key = None
    for key in keys:
        for name in _all(kb, "location_cost(K, F)", "F", K=key):
            if all(name != f for _, f in layers):
                layers.append((key, name))
        validators.extend(_all(kb, "location_validator(K, V)", "V", K=key))
        if robot_key is None and kb.holds("location_robot_key(K)", K=key):
            robot_key = key
    return LocationPlan(tuple(layers), tuple(dict.fromkeys(validators)), robot_key)
