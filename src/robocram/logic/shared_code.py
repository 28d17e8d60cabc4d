"""Generated code shared by knowledge bases that read the same texts.

Every new world's knowledge base consults the same texts (motion groundings, the process
module interface, the robot's facts), and their clause templates are read once per
process (see shared_reads.py): yet each knowledge base generated its procedures and
clause functions again, about 18 procedures and 45 clauses in a cold PR2 transport
(~6 ms). Generated code is a function of the clause templates and of what code
generation asked of the knowledge base: the one clause of a small callee compiled in
(inline_calls.py) and whether a callee's procedure is called directly (direct_calls.py).

So a procedure is kept by its clauses' templates (by identity: an entry holds them, so
their ids stay theirs; and by content, for facts made afresh for each world, such as a
robot's description) and reused by another knowledge base when each of those lookups
finds the same there, asked again in the same order (a direct callee not compiled yet
is compiled then, as generating the code would have). Its knowledge-base-specific
constants are bound afresh: the knowledge base, its generation (the guard of what was
compiled in), the predicate's Scan and the callees' procedures, and its level is
recomputed from theirs. When a lookup finds something else (a clause asserted,
retracted or consulted differently, a predicate made dynamic) the code is generated as
before. A clause function holds nothing of its knowledge base and is shared as it is.
Code generation reads no flag: the same clauses make the same code in any knowledge base.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Sequence
from dataclasses import dataclass

from robocram.logic.codegen import Bound, ClauseCode, ClauseFn, ClauseWriter, compile_clause_fn
from robocram.logic.direct_calls import LEVELS, callee_at
from robocram.logic.goal_writer import function_factory
from robocram.logic.inline_calls import CalleeTable, Lookup, inline_clause
from robocram.logic.lru import LRUCache
from robocram.logic.template import Slot, Tmpl
from robocram.logic.terms import Term
from robocram.logic.value import Value

__all__ = ["SHARED_PROCEDURES", "SharedProcedure", "SharedProcedures", "shared_clause_fn"]

KEPT = 1024  # procedures and clause functions kept (a transport compiles ~18 and ~45)
VARIANTS = 4  # procedures kept per clause templates (see SharedProcedures)
ProcKey = tuple[Hashable, bool, bool, bool]  # the clauses' templates, then the flags
Templates = tuple[tuple[tuple[Value, ...], tuple[Value, ...]], ...]


@dataclass(frozen=True)
class SharedProcedure:
    """A procedure's generated source and constants, less what is bound per knowledge base."""

    templates: Templates  # held so that the key's ids stay these templates'
    source: str
    consts: tuple[Value, ...]  # None at the bound positions
    bound: tuple[tuple[int, Bound], ...]
    seen: tuple[Lookup, ...]

    def bind(self, callees: CalleeTable | None, scan: object) -> Callable[..., object] | None:
        """The procedure for knowledge base `callees`, or None when a lookup finds
        something else there (the code must be generated again)."""
        procs: list[Callable[..., object]] = []
        level = 0
        for kind, key, found in self.seen:
            if callees is None:
                return None
            if kind == "inline":
                now = inline_clause(callees, key)
                if not _same_clause(now, found):
                    return None
                continue
            callee = callee_at(callees, key)
            if (callee is not None) != found:
                return None
            if callee is not None:
                procs.append(callee[0])
                level = max(level, callee[1] + 1)
        consts = list(self.consts)
        for i, mark in self.bound:
            if mark == "table":
                consts[i] = callees
            elif mark == "generation":
                consts[i] = callees._generation if callees is not None else None
            elif mark == "scan":
                consts[i] = scan
            else:
                consts[i] = procs[int(mark)]
        proc: Callable[..., object] = function_factory(self.source, "proc")(*consts)
        LEVELS[proc] = level
        return proc


def _same_clause(now: tuple[object, object] | None, found: object) -> bool:
    """Whether two inline lookups found the same clause templates (or both none)."""
    if now is None or not isinstance(found, tuple):
        return now is None and found is None
    return now[0] is found[0] and now[1] is found[1]


class SharedProcedures:
    """Procedures kept by their clauses' templates, for any knowledge base to bind.

    A key keeps up to VARIANTS procedures, the last generated first: knowledge bases
    that load the same caller over different callees take turns.
    """

    def __init__(self, size: int = KEPT) -> None:
        self._kept: LRUCache[ProcKey, tuple[SharedProcedure, ...]] = LRUCache(size)

    @staticmethod
    def key(clauses: Sequence[ClauseCode], owner: object, callees: object, direct: bool) -> ProcKey:
        """The key of a compilation: its clauses' templates and how it was asked for."""
        ids = tuple((id(c.head), id(c.body_rev), c.name) for c in clauses)
        return ids, owner is not None, callees is not None, direct

    def bind(
        self,
        key: ProcKey,
        clauses: Sequence[ClauseCode],
        callees: CalleeTable | None,
        scan: object,
    ) -> Callable[..., object] | None:
        """A procedure kept for `key` (else for clauses of the same content) bound to
        `callees` (see SharedProcedure.bind); None when there is none to reuse."""
        found = self._kept.get(key) or self._kept.get(_content_key(clauses, key))
        for shared in found or ():
            proc = shared.bind(callees, scan)
            if proc is not None:
                return proc
        return None

    def keep(
        self, key: ProcKey, clauses: Sequence[ClauseCode], source: str, writer: ClauseWriter
    ) -> None:
        """Keep what `writer` generated from `clauses` (its source) for `key`."""
        bound = tuple(writer.bound or ())
        consts = list(writer.consts)
        for i, _ in bound:
            consts[i] = None
        templates = tuple((c.head, c.body_rev) for c in clauses)
        seen = tuple(writer.seen or ())
        shared = SharedProcedure(templates, source, tuple(consts), bound, seen)
        for k in (key, _content_key(clauses, key)):
            before = self._kept.get(k) or ()
            self._kept.put(k, (shared, *before[: VARIANTS - 1]))


def _content_key(clauses: Sequence[ClauseCode], key: ProcKey) -> ProcKey:
    """`key` with each clause's templates by what they hold, not by identity.

    Facts made afresh for each world (a robot's description) hold the same atoms,
    numbers and compounds each time. The types are part of the key (1, 1.0 and True are
    equal in Python, not in Prolog); anything else (a Python object, a NaN, a string)
    stands for itself, and an entry holds the templates, so its id stays its own.
    """
    parts = tuple((_contents(c.head), _contents(c.body_rev), c.name) for c in clauses)
    return ("content", parts), *key[1:]


def _contents(templates: tuple[Value, ...]) -> Hashable:
    """What a head's arguments or a body's goals hold (see _content)."""
    return tuple([_content(t) for t in templates])


def _content(t: Value) -> Hashable:
    """What template `t` holds, as a hashable value (see _content_key)."""
    kind = type(t)
    if kind is str:
        return t
    if kind is Term:
        return ("term", t[0], tuple([_content(a) for a in t[1]]))
    if kind is Tmpl:
        return ("tmpl", t.name, tuple([_content(a) for a in t.args]))
    if kind is Slot:
        return ("slot", t.i)
    if kind is int:
        return ("int", t)
    if kind is float and t == t:
        return ("float", t.hex())
    return ("object", id(t))


SHARED_PROCEDURES = SharedProcedures()
_CLAUSE_FNS: LRUCache[Hashable, tuple[Templates, ClauseFn]] = LRUCache(KEPT)


def shared_clause_fn(clause: ClauseCode) -> ClauseFn:
    """`compile_clause_fn(clause)`, made once per clause templates (by identity, else by
    content: see _content_key; an entry holds the templates)."""
    key = (id(clause.head), id(clause.body_rev), clause.name)
    kept = _CLAUSE_FNS.get(key)
    if kept is None:
        content = ("content", _contents(clause.head), _contents(clause.body_rev), clause.name)
        by_content = _CLAUSE_FNS.get(content)
        fn = compile_clause_fn(clause) if by_content is None else by_content[1]
        kept = ((clause.head, clause.body_rev),), fn  # held: `key` stays these templates'
        if by_content is None:
            _CLAUSE_FNS.put(content, kept)
        _CLAUSE_FNS.put(key, kept)
    return kept[1]
