"""A predicate's definition: clauses with a lazy first-argument index, or built-in code."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

from robocram.logic.bulk import paused_gc
from robocram.logic.clause import Clause
from robocram.logic.inline_calls import CalleeTable
from robocram.logic.procedure import Procedure, compile_procedure
from robocram.logic.terms import Term, Var
from robocram.logic.value import Value

__all__ = ["CONTROL", "DET", "NONDET", "USER", "WARM_CALLS", "FrozenPred", "Key", "Pred"]

USER, DET, NONDET, CONTROL = 0, 1, 2, 3
WARM_CALLS = 3
Key = tuple[str, int]

# A predicate's built-in: a DetFn or a NondetFn (see engine.py) by its kind, None for user
# predicates. The machine calls it after testing the kind, which mypy cannot tie to the None
# case, so it is Any.
PredFn = Any


class Pred:
    """One name/arity: user clauses (plus an optional Python predicate) or a built-in."""

    __slots__ = (
        "arity",
        "dynamic",
        "erased",
        "extendable",
        "fn",
        "head",
        "index",
        "kind",
        "name",
        "owner",
        "proc",
        "pyfn",
        "skip",
        "store",
        "system",
        "varclauses",
        "warm",
    )

    def __init__(self, name: str, arity: int, kind: int = USER, fn: PredFn = None) -> None:
        self.name = name
        self.arity = arity
        self.kind = kind
        self.fn = fn
        # The clauses are store[head:]; before head: room (None). Readers slice past `head`,
        # which mypy cannot follow from an element type, so the items are Any.
        self.store: list[Any] = []
        self.head = 0
        self.index: dict[object, list[Clause]] | None = None
        self.varclauses: list[Clause] = []
        self.pyfn: Callable[..., Iterator[object]] | None = None
        self.dynamic = False
        self.system = False
        self.owner: str | None = None
        self.extendable: set[str] = set()
        self.proc: Procedure | None = None
        self.warm = 0
        self.erased = 0  # retracted clauses still in `clauses` (dropped in batches)
        # (store, lo, i): every clause in store[lo:i] is retracted, so a scan of the
        # clauses from lo may start at i (retracting the first clause again and again).
        self.skip: tuple[list[Clause], int, int] | None = None

    def warm_up(self, callees: CalleeTable | None = None) -> None:
        """Count a call; on the third, compile the switching procedure if it qualifies.

        `callees`: the knowledge base whose small one-clause predicates the procedure may
        compile in (see inline_calls.py); None for a predicate that several share.
        """
        self.warm += 1
        if self.warm == WARM_CALLS and not self.dynamic and self.pyfn is None:
            self.proc = compile_procedure(self.clauses, self, callees)

    def callee_procedure(self, callees: CalleeTable | None) -> Procedure | None:
        """The procedure a caller may call directly (see direct_calls.py): the compiled
        one, or, for a static user predicate of the caller's knowledge base not compiled
        yet, one compiled now without direct calls of its own; None for the others."""
        if self.proc is not None or self.kind != USER or self.dynamic or self.pyfn is not None:
            return self.proc if self.kind == USER and self.pyfn is None else None
        if self.system or self.owner == "library":  # fact_groups.LIBRARY_OWNER: shared code
            return None
        self.proc = compile_procedure(self.clauses, self, callees, direct=False)
        self.warm = max(self.warm, WARM_CALLS)
        return self.proc

    def copy(self) -> Pred:
        """A new predicate with the same definition (its own clause list and no code)."""
        twin = Pred(self.name, self.arity, self.kind, self.fn)
        twin.store = [c for c in self.clauses if not c.erased]
        twin.pyfn = self.pyfn
        twin.dynamic = self.dynamic
        twin.owner = self.owner
        twin.extendable = set(self.extendable)
        return twin

    @property
    def clauses(self) -> list[Clause]:
        """The clauses in order (a copy once asserta/1 has used the room at the front)."""
        return self.store[self.head :] if self.head else self.store

    @property
    def indicator(self) -> str:
        """The `name/arity` text."""
        return f"{self.name}/{self.arity}"

    def live(self, clauses: list[Clause]) -> list[Clause]:
        """`clauses` without the retracted ones (the same list when none is retracted)."""
        return [c for c in clauses if not c.erased] if self.erased else clauses

    def erase(self, clause: Clause) -> None:
        """Retract `clause` in O(1) amortised: mark it; drop marked ones in batches.

        Calls already running hold their own list of candidates (taken when they
        started), so they still see the clause: ISO's logical update view.
        """
        clause.erased = True
        self.erased += 1
        if self.erased > 8 and 2 * self.erased > len(self.store) - self.head:
            self.set_clauses([c for c in self.clauses if not c.erased])

    def set_clauses(self, clauses: list[Clause]) -> None:
        """Replace all clauses (a new list, so running queries keep their snapshot)."""
        self.store = clauses
        self.head = 0
        self.erased = 0
        self.skip = None
        self.index = None
        self.proc = None
        self.warm = 0

    def changed(self) -> None:
        """Forget the compiled procedure: the clauses changed."""
        self.proc = None
        self.warm = 0

    def add_last(self, clause: Clause) -> None:
        """Append a clause in place, keeping any built index up to date."""
        self.store.append(clause)
        self.changed()
        index = self.index
        if index is None:
            return
        if clause.key is None:
            self.varclauses.append(clause)
            for bucket in index.values():
                bucket.append(clause)
        else:
            found = index.get(clause.key)
            if found is None:
                found = index[clause.key] = list(self.varclauses)
            found.append(clause)

    def add_first(self, clause: Clause) -> None:
        """Prepend a clause in O(1) amortised (asserta/1), keeping the logical update view.

        The store keeps free room before `head`. A running call reads the clauses it
        started with as `store[lo:n]` with `lo >= head`, so writing at `head - 1` changes
        nothing it sees; when the room is used up, a new store gets as much room again
        as it has clauses. A built index gets the clause at the front of its bucket
        (a copy of that bucket), or is dropped for a clause with a variable there.
        """
        if self.head == 0:
            room = max(8, len(self.store))
            self.store = [None] * room + self.store
            self.head = room
        self.head -= 1
        self.store[self.head] = clause
        self.changed()
        index = self.index
        if index is None:
            return
        if clause.key is None:
            self.index = None  # rebuilt by the next call that needs it
        else:
            bucket = index.get(clause.key)
            index[clause.key] = [clause, *(self.varclauses if bucket is None else bucket)]

    def build_index(self) -> dict[object, list[Clause]]:
        """Group clauses by first-argument key; variable-first clauses join every bucket."""
        index: dict[object, list[Clause]] = {}
        varclauses: list[Clause] = []
        with paused_gc():
            for clause in self.clauses:
                if clause.key is None:
                    varclauses.append(clause)
                    for bucket in index.values():
                        bucket.append(clause)
                else:
                    found = index.get(clause.key)
                    if found is None:
                        found = index[clause.key] = list(varclauses)
                    found.append(clause)
        self.varclauses = varclauses
        self.index = index
        return index

    def first_live(self) -> int:
        """Where a scan of all clauses may start: past the retracted ones at the front.

        Retracted clauses are never restored and the positions from `head` on are only
        ever appended to, so the run found stays retracted; it is remembered for the
        next scan while the store and its start are unchanged.
        """
        store, i = self.store, self.head
        skip = self.skip
        if skip is not None and skip[0] is store and skip[1] == i:
            i = skip[2]
        n = len(store)
        while i < n and store[i].erased:
            i += 1
        self.skip = (store, self.head, i)
        return i

    def candidates(self, first: Value) -> list[Clause]:
        """Clauses whose first argument can match the dereferenced call argument `first`."""
        t = type(first)
        if t is Var:
            return self.clauses
        index = self.index
        if index is None:
            index = self.build_index()
        if t is Term:
            bucket = index.get((first[0], len(first[1])))
        else:
            try:
                bucket = index.get(first)
            except TypeError:
                return self.clauses
        return self.varclauses if bucket is None else bucket


class FrozenPred(Pred):
    """A system predicate: built once, shared read-only by every knowledge base."""

    __slots__ = ()

    def __init__(self, name: str, arity: int, kind: int, fn: PredFn = None) -> None:
        super().__init__(name, arity, kind, fn)
        self.owner = "system"
        self.system = True  # from here on, every attribute is read-only

    def __setattr__(self, attr: str, value: object) -> None:
        if getattr(self, "system", False):
            raise AttributeError(
                f"{self.name}/{self.arity} is a system predicate shared by every knowledge"
                f" base; it cannot be changed (tried to set {attr!r})"
            )
        super().__setattr__(attr, value)
