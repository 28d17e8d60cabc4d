"""The kinds of choicepoint: the first item of each entry on the machine's choicepoint stack.

CLAUSES resumes the next candidate clause, PROC a compiled procedure at a later clause
(see procedure.py), GEN a built-in's generator, ALT a disjunction's other branch; BARRIER,
CATCH, REACT and DEAD mark nested solves, catch/3 frames and cut-away entries.
"""

from __future__ import annotations

__all__ = ["ALT", "BARRIER", "CATCH", "CLAUSES", "DEAD", "GEN", "PROC", "REACT"]

CLAUSES, ALT, GEN, BARRIER, CATCH, REACT, DEAD, PROC = range(8)
