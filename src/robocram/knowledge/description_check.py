"""Check that a robot's facts state every predicate the table marks required.

A predicate with ``Need.ROBOT`` needs a fact per robot, one with ``Need.ARM`` a fact per
arm of ``arm/2``. Each gap is reported with the predicate's one-line meaning, so a
description written by hand (in Python or in Prolog) says what it still lacks.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from robocram.knowledge.errors import MissingFact, MissingFactsError
from robocram.knowledge.predicate import Answers, Need, Predicate, Source
from robocram.knowledge.predicate_table import predicates_of
from robocram.knowledge.robot_predicates import ARM
from robocram.logic.errors import UnknownPredicateError
from robocram.logic.terms import Term


def missing_in_facts(facts: Iterable[Term]) -> list[MissingFact]:
    """The required facts missing from ``facts`` (one robot's, or several robots')."""
    stated: set[tuple[str, tuple[Any, ...]]] = set()
    robots: list[str] = []
    arms: list[tuple[str, str]] = []
    for fact in facts:
        names = tuple(str(a) for a in fact.args[:2] if isinstance(a, str))  # robot, arm
        stated.add((f"{fact.name}/{fact.arity}", names[:1]))
        stated.add((f"{fact.name}/{fact.arity}", names))
        if fact.name == "robot" and fact.arity == 1:
            robots.append(str(fact.args[0]))
        elif fact.name == ARM.name and fact.arity == ARM.arity:
            arms.append((str(fact.args[0]), str(fact.args[1])))
    missing = []
    for p in predicates_of(Source.DESCRIPTION):
        if p.need is Need.ROBOT:
            missing += [
                MissingFact(r, None, p.indicator, p.meaning)
                for r in robots
                if (p.indicator, (r,)) not in stated
            ]
        elif p.need is Need.ARM:
            missing += [
                MissingFact(r, a, p.indicator, p.meaning)
                for r, a in arms
                if (p.indicator, (r, a)) not in stated
            ]
    return missing


def _states(kb: Answers, p: Predicate[Any], **bound: str) -> bool:
    try:
        return p.holds(kb, **bound)
    except UnknownPredicateError:  # not even declared: certainly not stated
        return False


def missing_in_kb(kb: Answers, robot_name: str) -> list[MissingFact]:
    """The required facts about ``robot`` that the knowledge base ``kb`` does not state."""
    missing = []
    arms = [row.arm for row in ARM.answers(kb, robot=robot_name)] if _states(kb, ARM) else []
    for p in predicates_of(Source.DESCRIPTION):
        if p.need is Need.ROBOT and not _states(kb, p, robot=robot_name):
            missing.append(MissingFact(robot_name, None, p.indicator, p.meaning))
        elif p.need is Need.ARM:
            missing += [
                MissingFact(robot_name, a, p.indicator, p.meaning)
                for a in arms
                if not _states(kb, p, robot=robot_name, arm=a)
            ]
    return missing


def check_facts(facts: Iterable[Term]) -> None:
    """Raise :class:`MissingFactsError` listing every required fact ``facts`` lack."""
    missing = missing_in_facts(facts)
    if missing:
        raise MissingFactsError(missing)
