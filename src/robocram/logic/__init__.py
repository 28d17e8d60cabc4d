"""An embedded Prolog that lives with Python objects: knowledge bases, fact groups, queries."""

from robocram.logic.context import current_kb, using_kb
from robocram.logic.errors import (
    FactGroupError,
    InferenceLimitExceeded,
    PrologDomainError,
    PrologError,
    PrologEvaluationError,
    PrologExistenceError,
    PrologHostError,
    PrologInstantiationError,
    PrologOccursCheckError,
    PrologPermissionError,
    PrologResourceError,
    PrologSyntaxError,
    PrologThrow,
    PrologTypeError,
    TimeLimitExceeded,
    UnknownPredicateError,
)
from robocram.logic.gc_pacing import fast_queries
from robocram.logic.knowledge_base import KnowledgeBase
from robocram.logic.name_atom import name_atom
from robocram.logic.terms import Term, Var
from robocram.logic.usage_errors import LogicArgumentError, LogicError, LogicUsageError
from robocram.logic.value import Value

__all__ = [
    "FactGroupError",
    "InferenceLimitExceeded",
    "KnowledgeBase",
    "LogicArgumentError",
    "LogicError",
    "LogicUsageError",
    "PrologDomainError",
    "PrologError",
    "PrologEvaluationError",
    "PrologExistenceError",
    "PrologHostError",
    "PrologInstantiationError",
    "PrologOccursCheckError",
    "PrologPermissionError",
    "PrologResourceError",
    "PrologSyntaxError",
    "PrologThrow",
    "PrologTypeError",
    "Term",
    "TimeLimitExceeded",
    "UnknownPredicateError",
    "Value",
    "Var",
    "current_kb",
    "fast_queries",
    "name_atom",
    "using_kb",
]
