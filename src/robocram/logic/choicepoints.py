"""The kinds of choicepoint: the first item of each entry on the machine's choicepoint stack.

CLAUSES resumes the next candidate clause, PROC a compiled procedure at a later clause
(see procedure.py), GEN a built-in's generator, ALT a disjunction's other branch; BARRIER,
CATCH, REACT and DEAD mark nested solves, catch/3 frames and cut-away entries.
"""

from __future__ import annotations

from typing import Any

__all__ = [
    "ALT",
    "BARRIER",
    "CATCH",
    "CLAUSES",
    "DEAD",
    "GEN",
    "PROC",
    "REACT",
    "ChoicePoint",
    "Cont",
]

CLAUSES, ALT, GEN, BARRIER, CATCH, REACT, DEAD, PROC = range(8)

# A choicepoint is a list whose first item is its kind and whose other items depend on the
# kind (a trail mark, a generator, candidate clauses, a continuation ...). The machine reads
# them by position, so no type narrower than Any fits them without changing the entries.
ChoicePoint = list[Any]
# A continuation: a `(goal, cut barrier, next)` chain, None (a solution), False or FAIL
# (failure), or a list a procedure hands back. The hot loop tells these apart by identity
# and `type(...) is` tests, which mypy cannot follow, and unpacks the chain, so it is Any.
Cont = Any
