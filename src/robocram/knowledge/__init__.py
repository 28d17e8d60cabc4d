"""The predicate table: typed predicates of the knowledge base, declared once.

From each :class:`Predicate` row come the registrations of the world's and the grasp
model's Python predicates, typed queries returning frozen dataclasses (what plans use
instead of Prolog strings), the facts of a robot description, the check that a
description states every required predicate, and ``docs/predicates.md``.
"""

from robocram.knowledge.argument import Argument, JointStates, Names, Vector, unit
from robocram.knowledge.description_check import check_facts, missing_in_facts, missing_in_kb
from robocram.knowledge.errors import (
    ImplementationMismatch,
    KnowledgeError,
    KnowledgeUsageError,
    MissingFact,
    MissingFactsError,
    UnknownArgumentError,
)
from robocram.knowledge.predicate import Need, Predicate, Source
from robocram.knowledge.predicate_table import PREDICATE_TABLE, indicators_of, predicates_of
from robocram.knowledge.registration import register_predicates

__all__ = [
    "Argument",
    "ImplementationMismatch",
    "JointStates",
    "KnowledgeError",
    "KnowledgeUsageError",
    "MissingFact",
    "MissingFactsError",
    "Names",
    "Need",
    "PREDICATE_TABLE",
    "Predicate",
    "Source",
    "UnknownArgumentError",
    "Vector",
    "check_facts",
    "indicators_of",
    "missing_in_facts",
    "missing_in_kb",
    "predicates_of",
    "register_predicates",
    "unit",
]
