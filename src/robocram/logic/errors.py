"""The engine's exception hierarchy: one root, `PrologError`, carrying the Prolog error term.

Errors raised by built-ins are ISO error terms `error(Formal, Context)`; inside a query they
can be caught with `catch/3`, and when they escape they surface as the matching subclass.
"""

from __future__ import annotations

from robocram.logic.convert import to_python
from robocram.logic.terms import Term, format_term
from robocram.logic.value import Value

__all__ = [
    "FactGroupError",
    "InferenceLimitExceeded",
    "PrologDomainError",
    "PrologError",
    "PrologEvaluationError",
    "PrologExistenceError",
    "PrologInstantiationError",
    "PrologHostError",
    "PrologOccursCheckError",
    "PrologPermissionError",
    "PrologResourceError",
    "PrologSyntaxError",
    "PrologThrow",
    "PrologTypeError",
    "TimeLimitExceeded",
    "UnknownPredicateError",
    "error_from_ball",
]


class PrologError(Exception):
    """Root of all engine errors; `ball` is the Prolog term thrown (engine form)."""

    def __init__(self, message: str, ball: Value = None) -> None:
        super().__init__(message)
        self.message = message
        self.ball: Value = (
            ball if ball is not None else Term("error", (Term("system_error", (message,)), message))
        )

    @property
    def term(self) -> Value:
        """The thrown term as a Python value (lists as lists, atoms as str)."""
        return to_python(self.ball)


def _iso(formal: Value, message: str) -> Term:
    return Term("error", (formal, message))


class PrologThrow(PrologError):
    """A term thrown with `throw/1` that no `catch/3` caught."""

    def __init__(self, ball: Value) -> None:
        super().__init__(f"uncaught exception in query: {format_term(ball, quoted=True)}", ball)


class PrologInstantiationError(PrologError):
    """An argument was unbound where a value is needed."""

    def __init__(self, message: str) -> None:
        super().__init__(message, _iso("instantiation_error", message))


class PrologTypeError(PrologError):
    """An argument had the wrong type (`type_error(Expected, Culprit)`)."""

    def __init__(self, expected: str, culprit: Value, message: str) -> None:
        super().__init__(message, _iso(Term("type_error", (expected, culprit)), message))
        self.expected = expected
        self.culprit = culprit


class PrologDomainError(PrologError):
    """An argument had the right type but an invalid value."""

    def __init__(self, domain: str, culprit: Value, message: str) -> None:
        super().__init__(message, _iso(Term("domain_error", (domain, culprit)), message))


class PrologEvaluationError(PrologError):
    """Arithmetic failed (`evaluation_error(zero_divisor)` and friends)."""

    def __init__(self, what: str, message: str) -> None:
        super().__init__(message, _iso(Term("evaluation_error", (what,)), message))


class PrologExistenceError(PrologError):
    """Something named does not exist (`existence_error(Kind, Name)`)."""

    def __init__(self, kind: str, culprit: Value, message: str) -> None:
        super().__init__(message, _iso(Term("existence_error", (kind, culprit)), message))


class UnknownPredicateError(PrologExistenceError):
    """A goal called a predicate with no definition; `similar` lists near names."""

    def __init__(self, name: str, arity: int, similar: list[str]) -> None:
        hint = f"; did you mean {', '.join(similar)}?" if similar else ""
        msg = f"unknown predicate {name}/{arity}{hint}"
        super().__init__("procedure", Term("/", (name, arity)), msg)
        self.name = name
        self.arity = arity
        self.similar = similar


class PrologPermissionError(PrologError):
    """An operation is not allowed on the object (e.g. modifying a static predicate)."""

    def __init__(self, action: str, kind: str, culprit: Value, message: str) -> None:
        super().__init__(message, _iso(Term("permission_error", (action, kind, culprit)), message))


class FactGroupError(PrologPermissionError):
    """A fact group added clauses to a predicate another group owns and did not share."""

    def __init__(self, indicator: str, owner: str, group: str) -> None:
        msg = (
            f"fact group '{group}' adds clauses to {indicator}, which fact group '{owner}' owns;"
            f" declare it extendable (extendable=['{indicator}']) in '{group}' or '{owner}'"
        )
        super().__init__("modify", "fact_group_predicate", indicator, msg)
        self.indicator = indicator
        self.owner = owner
        self.group = group


class PrologSyntaxError(PrologError):
    """Prolog text could not be read; names the line, column and offending text."""

    def __init__(self, reason: str, line: int, column: int, text: str) -> None:
        msg = f"syntax error at line {line}, column {column}: {reason}: {text!r}"
        super().__init__(msg, _iso(Term("syntax_error", (reason,)), msg))
        self.reason = reason
        self.line = line
        self.column = column
        self.text = text


class PrologOccursCheckError(PrologError):
    """With the flag `occurs_check = error`: a unification would make a cyclic term."""

    def __init__(self, var: Value, term: Value) -> None:
        message = (
            f"unifying {var!r} with {term!r} would make a cyclic term (occurs_check is error);"
            " set it to false or true to unify or fail instead"
        )
        super().__init__(message, _iso(Term("occurs_check", (var, term)), message))


class PrologResourceError(PrologError):
    """A resource ran out: term depth, integer size, inferences, time (`resource_error(R)`)."""

    def __init__(self, resource: str, message: str) -> None:
        super().__init__(message, _iso(Term("resource_error", (resource,)), message))
        self.resource = resource


class InferenceLimitExceeded(PrologResourceError):
    """A query ran more inferences than its `max_inferences`."""

    def __init__(self, limit: int) -> None:
        super().__init__(
            "inferences", f"query exceeded its limit of {limit} inferences (max_inferences)"
        )
        self.limit = limit


class TimeLimitExceeded(PrologResourceError):
    """A query ran longer than its `time_limit` [s]."""

    def __init__(self, limit: float) -> None:
        super().__init__("time", f"query exceeded its time limit of {limit} s (time_limit)")
        self.limit = limit


class PrologHostError(PrologError):
    """A Python exception raised inside a built-in or a Python predicate called by `goal`.

    Inside the query it is the catchable `error(python_error(Class, Message), Context)`;
    when nothing catches it, the query re-raises `original` itself.
    """

    def __init__(self, original: Exception, goal: str) -> None:
        kind = type(original).__name__
        msg = f"{goal} raised {kind}: {original}"
        formal = Term("python_error", (kind, str(original)))
        super().__init__(msg, _iso(formal, msg))
        self.original = original
        self.goal = goal


def error_from_ball(ball: Value) -> PrologError:
    """Wrap a thrown term that escaped a query in the matching Python exception."""
    if type(ball) is Term and ball[0] == "error" and len(ball[1]) == 2:
        formal, context = ball[1]
        msg = context if isinstance(context, str) else format_term(ball, quoted=True)
        classes: dict[str, type[PrologError]] = {
            "type_error": PrologTypeError,
            "instantiation_error": PrologInstantiationError,
            "domain_error": PrologDomainError,
            "evaluation_error": PrologEvaluationError,
            "existence_error": PrologExistenceError,
            "permission_error": PrologPermissionError,
            "resource_error": PrologResourceError,
        }
        key = formal[0] if type(formal) is Term else formal
        cls = classes.get(key) if isinstance(key, str) else None
        if cls is not None:
            err = cls.__new__(cls)
            PrologError.__init__(err, msg, ball)
            return err
    return PrologThrow(ball)
