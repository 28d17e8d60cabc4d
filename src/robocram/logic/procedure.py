"""Compile a static predicate into one Python function that tries its clauses in order.

Running clause by clause through the machine costs a choicepoint per call of a predicate
with two or more clauses, and a trip round the goal dispatch per clause tried. The
generated procedure instead runs each clause's head unification and leading inline
built-ins (comparisons, `is/2`, `=/2`, cut) in one frame, undoing the trail and falling
through to the next clause when one fails there ("shallow backtracking"). It pushes a
choicepoint only when a clause has got past those and a later clause can still match
the first argument; a cut among them commits to the clause, so `tak/4`, `p_remove/3`
or `d/3` of deriv never make one. A clause ending in a call to the predicate itself
loops in the same frame.

    proc(args, trail, nxt, cps, start) -> continuation, or False when no clause from
        `start` on gets past its inline goals; or the argument list plus one extra item:
        None after PROC_LOOPS loops, so that the machine counts them and calls again,
        or a Scan to have the machine run the clauses one by one

The first argument is switched on before any clause runs: for each principal functor
or constant in the clause heads, a branch holds the code of just the clauses that can
match it (in order, the variable ones included), with the first argument's functor
already known; a call with it unbound runs every clause. The last clause of a branch
leaves no choicepoint and runs without the try-next wrapper.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from robocram.logic.choicepoints import PROC, ChoicePoint, Cont
from robocram.logic.codegen import ClauseCode, ClauseWriter
from robocram.logic.direct_calls import LEVELS
from robocram.logic.exclusive_guards import excludes
from robocram.logic.goal_writer import function_factory
from robocram.logic.inline_calls import CalleeTable
from robocram.logic.limits import PROC_LOOPS
from robocram.logic.shared_code import SHARED_PROCEDURES
from robocram.logic.template import Slot, Tmpl
from robocram.logic.terms import Term, Var
from robocram.logic.value import Value

__all__ = ["MAX_CLAUSES", "SCAN_AFTER", "Procedure", "Scan", "compile_procedure"]

Procedure = Callable[[Sequence[Value], list[Var], Cont, list[ChoicePoint], int], Cont]
MAX_CLAUSES = 64
MAX_KEYS = MAX_CLAUSES  # distinct first-argument keys in one procedure
SCAN_AFTER = 8  # clauses a call with an unbound first argument tries in the procedure
_CHAIN = 6  # up to this many keys of a kind, compare in turn; beyond, a dictionary


class _Maybe:
    """The switch key of a call whose first argument is unbound or not indexable."""

    def __repr__(self) -> str:
        return "MAYBE"


MAYBE = _Maybe()


class Scan:
    """Handed back (last in the argument list) to have the machine run `pred` clause by clause."""

    __slots__ = ("pred",)

    def __init__(self, pred: object) -> None:
        self.pred = pred


def compile_procedure(
    stored: Sequence[ClauseCode],
    owner: object = None,
    callees: CalleeTable | None = None,
    direct: bool = True,
) -> Procedure | None:
    """Return the procedure of a static predicate's clauses, or None when not worth it.

    With `owner` (the predicate), a call with the first argument unbound that would try
    more than SCAN_AFTER clauses is handed back to the machine, which resumes each clause
    in O(1) instead of re-entering the procedure. With `callees` (the knowledge base),
    calls of small one-clause predicates are compiled in (see inline_calls.py), and,
    unless not `direct`, a leading call of a compiled procedure is made directly (see
    direct_calls.py). Code generated for the same clauses before (for any knowledge
    base) is bound to this one instead of generated again (see shared_code.py).
    """
    clauses = list(stored)
    if not 1 <= len(clauses) <= MAX_CLAUSES:
        return None
    key = SHARED_PROCEDURES.key(clauses, owner, callees, direct)
    proc = SHARED_PROCEDURES.bind(key, clauses, callees, Scan(owner))
    if proc is not None:
        return proc
    branches = _branches(clauses)
    if branches is None:
        return None
    try:
        writer = _ProcWriter(clauses, owner)
        writer.callees = callees
        writer.direct = direct
        writer.procedure(branches)
        head = "def proc(args, trail, nxt, cps, start):"
        source = "\n".join([head, *writer.lines, ""])
        proc = function_factory(source, "proc")(*writer.consts)
        LEVELS[proc] = writer.level
    except (SyntaxError, RecursionError, MemoryError):
        return None  # too deeply nested to compile; the clauses run one by one instead
    SHARED_PROCEDURES.keep(key, clauses, source, writer)
    return proc


Key = tuple[str, int] | str | int


class _Branches:
    """Which clauses each kind of first argument can match, in clause order."""

    def __init__(self) -> None:
        self.compound: dict[tuple[str, int], list[int]] = {}
        self.atomic: dict[str | int, list[int]] = {}
        self.open: list[int] = []  # clauses with a variable (or float, ...) there
        self.open_compound: list[int] = []  # those of them a compound can get past
        self.every: list[int] = []


def _branches(clauses: list[ClauseCode]) -> _Branches | None:
    """Group the clauses by first-argument key; None when too many keys or copies."""
    b = _Branches()
    b.every = list(range(len(clauses)))
    if not clauses[0].head:
        return b
    keys = [_key(c.head[0]) for c in clauses]
    for k in keys:
        if type(k) is tuple:
            b.compound.setdefault(k, [])
        elif k is not None:
            b.atomic.setdefault(k, [])  # type: ignore[arg-type]
    if len(b.compound) + len(b.atomic) > MAX_KEYS:
        return None
    for i, k in enumerate(keys):
        if k is None:
            b.open.append(i)
        for table in (b.compound, b.atomic):
            for key, members in table.items():
                if k is None or k == key and type(k) is type(key):
                    members.append(i)
    for key, members in b.compound.items():
        b.compound[key] = [i for i in members if not _refused(clauses[i], Term)]
    for key, members in b.atomic.items():
        b.atomic[key] = [i for i in members if not _refused(clauses[i], type(key))]
    b.open_compound = [i for i in b.open if not _refused(clauses[i], Term)]
    copies = sum(len(m) for m in [*b.compound.values(), *b.atomic.values()])
    return b if copies <= 4 * len(clauses) + 32 else None


# Whether each ISO type test holds for a compound, an atom and an integer
_TEST_TRUTH: dict[str, tuple[bool, bool, bool]] = {
    "var": (False, False, False),
    "nonvar": (True, True, True),
    "atom": (False, True, False),
    "number": (False, False, True),
    "integer": (False, False, True),
    "float": (False, False, False),
    "atomic": (False, True, True),
    "compound": (True, False, False),
    "callable": (True, True, False),
}
_KINDS: dict[type, int] = {Term: 0, str: 1, int: 2}


def _refused(clause: ClauseCode, kind: type) -> bool:
    """True when a type test leading the body fails for any first argument of type `kind`.

    `p(X, ...) :- atomic(X), ...` can never run for a compound X: head unification binds
    only variables, so the test sees the type the switch saw. Only tests that neither
    bind nor raise may come before it (a cut or a comparison stops the scan).
    """
    if not clause.head or type(clause.head[0]) is not Slot:
        return False
    first = clause.head[0].i
    for goal in reversed(clause.body_rev):
        if type(goal) is not Tmpl or len(goal.args) not in (1, 2):
            return False
        if len(goal.args) == 2:
            if goal.name not in ("==", "\\=="):
                return False
            continue
        truth = _TEST_TRUTH.get(goal.name)
        if truth is None:
            return False
        arg = goal.args[0]
        if type(arg) is Slot and arg.i == first and not truth[_KINDS[kind]]:
            return True
    return False


def _key(t: Value) -> Key | None:
    """The switch key of a head's first argument; None when any call argument can match."""
    if type(t) is Tmpl:
        return (t.name, len(t.args))
    if type(t) is Term:
        return (t[0], len(t[1]))
    if type(t) is str or type(t) is int:
        return t
    return None  # a variable, a float (1.0 = 1 in Python) or an opaque constant


class _ProcWriter(ClauseWriter):
    """Writes the switch and, per branch, each clause; a failing clause falls through."""

    def __init__(self, clauses: list[ClauseCode], owner: object = None) -> None:
        super().__init__()
        self.clauses = clauses
        self.owner = owner
        self.arity = len(clauses[0].head)
        self.names = "".join(f"a{i}, " for i in range(self.arity))
        self.committed: bool | None = False
        self.next_start: int | None = None
        self.alt_start: int | None = None  # the clause a choicepoint resumes at
        self.seen = []
        self.bound = []

    def procedure(self, b: _Branches) -> None:
        self.switch(b)
        body = "\n".join(self.lines)
        self.lines = []
        if self.arity:
            self.emit(f"{self.names}= args", 1)
        loops = "continue" in body
        # The trail only serves choicepoints: with none, drop it on entry, and again
        # every PROC_LOOPS loops, when a long self-recursion is handed to the machine
        # so that it counts the inferences (limits, stop requests) and calls again.
        self.emit("if not cps and trail: del trail[:]", 1)
        if loops:  # counted where a self-call loops (see self_call)
            self.emit("steps = 1", 1)
        self.emit("while True:", 1)
        if re.search(r"\bcb\b", body):
            self.emit("cb = len(cps)", 2)
        self.lines.append(body)

    def switch(self, b: _Branches) -> None:
        """Emit the switch on the first argument into each branch's clauses."""
        scan = self.owner is not None and len(b.every) > SCAN_AFTER
        keyless = not b.compound and not b.atomic and len(b.open_compound) == len(b.every)
        if not self.arity or keyless and not scan:
            # No head names a first argument and no leading type test refuses a compound
            # there (or there is none): every call runs every clause, so no switch.
            self.branch(b.every, 2, switched=False)
            return
        # The type is taken once for a bound first argument (the common call), not twice.
        self.emit("t = type(a0)", 2)
        self.emit("while t is Var and a0.ref is not None: a0 = a0.ref; t = type(a0)", 2)
        self.emit("if t is Term:", 2)
        if len({k[0] for k in b.compound}) == len(b.compound):
            # No two keys share a name (the common case): the switch reads the name only;
            # the arity is checked by the clauses' unpacking of the arguments.
            named: list[tuple[Value, list[int]]] = [(k[0], m) for k, m in b.compound.items()]
            if len(named) > 1:
                self.emit("f = a0[0]", 3)
            first = "f" if len(named) > 1 else "a0[0]"
            tests = [f"{first} == {self.const(k)}" for k, _ in named]
            self.dispatch(named, tests, "f", b.open_compound, name_only=True)
        else:
            self.emit("f = a0[0]; n = len(a0[1])", 3)
            tests = [f"f == {self.const(k[0])} and n == {k[1]}" for k in b.compound]
            self.dispatch(list(b.compound.items()), tests, "(f, n)", b.open_compound)
        self.emit("elif t is str or t is int:", 2)
        tests = [f"t is {type(k).__name__} and a0 == {self.const(k)}" for k in b.atomic]
        self.dispatch(list(b.atomic.items()), tests, "a0", b.open)
        self.emit("else:", 2)
        if scan:
            self.emit(f"return [{self.names}{self.bound_const(Scan(self.owner), 'scan')}]", 3)
        else:
            self.branch(b.every, 3, switched=False)

    def dispatch(
        self,
        entries: list[tuple[Value, list[int]]],
        tests: list[str],
        key: str,
        open_: list[int],
        name_only: bool = False,
    ) -> None:
        """Emit the branches of one kind of key: compared in turn, or by a dictionary.

        `name_only`: the tests (or the table) take a functor's name, not its arity (no two
        keys share a name); a branch's clauses
        holding the other arity then fail at their unpacking, leaving the clauses open to
        any first argument in the branch, as in the branch of no key.

        Past `_CHAIN` keys, a dictionary gives the branch number and a binary tree of
        comparisons on it leads to the branch, so a call costs log2(keys) comparisons.
        """
        if len(entries) <= _CHAIN:
            for j, (_, members) in enumerate(entries):
                self.emit(f"{'el' if j else ''}if {tests[j]}:", 3)
                self.branch(members, 4, switched=True, arity_known=not name_only)
            self.other(open_, 3, bool(entries))
            return
        table = self.const({k: j for j, (k, _) in enumerate(entries)})
        self.emit(f"bn = {table}.get({key}, -1)", 3)
        self.emit("if bn < 0:", 3)
        self.branch(open_, 4, switched=False)
        self.emit("else:", 3)
        self.tree([m for _, m in entries], 0, len(entries), 4, not name_only)

    def tree(
        self, branches: list[list[int]], lo: int, hi: int, depth: int, arity_known: bool
    ) -> None:
        """Emit a binary search on `bn` over branches lo..hi-1."""
        if hi - lo == 1:
            self.branch(branches[lo], depth, switched=True, arity_known=arity_known)
            return
        mid = (lo + hi) // 2
        self.emit(f"if bn < {mid}:", depth)
        self.tree(branches, lo, mid, depth + 1, arity_known)
        self.emit("else:", depth)
        self.tree(branches, mid, hi, depth + 1, arity_known)

    def other(self, members: list[int], depth: int, chained: bool) -> None:
        """The branch for a key no clause names: the clauses open to any argument."""
        if chained:
            self.emit("else:", depth)
            depth += 1
        self.branch(members, depth, switched=False)

    def branch(
        self, members: list[int], depth: int, switched: bool, arity_known: bool = True
    ) -> None:
        """Emit the clauses `members` in order; all but the last fall through on failure."""
        if not members:
            self.emit("return False", depth)
            return
        if len(members) > 1:
            self.emit("mark = len(trail)", depth)
        for pos, i in enumerate(members):
            # Each clause's temporaries die with its block: numbering them afresh keeps
            # the function's locals few (CPython clears every local at each call's end).
            self.temps = 0
            self.base = 0
            self.committed = False
            last = pos == len(members) - 1
            self.next_start = None if last else members[pos + 1]
            rest = [j for j in members[pos + 1 :] if not excludes(self.clauses[i], self.clauses[j])]
            self.alt_start = rest[0] if rest else None
            if last:
                self.fail = "return False"
                self.base = depth - 1
                self.clause_code(self.clauses[i], switched, arity_known)
                continue
            self.fail = "break"
            self.emit(f"if start <= {i}:", depth)
            self.emit("while True:", depth + 1)
            self.base = depth + 1
            self.clause_code(self.clauses[i], switched, arity_known)
            self.base = 0
            self.emit("if start < 0: start = 0; continue", depth + 1)
            # the length taken once: a long trail's length is a new int at each reading
            self.emit("u = len(trail) - mark", depth + 1)
            self.emit("while u: trail.pop().ref = None; u -= 1", depth + 1)
        self.base = 0

    def arg_local(self, i: int, p: Value) -> str:
        """A copy of argument `i` when a later clause of the branch may still read it.

        Unifying a head argument dereferences its local in place; past the first
        argument, an earlier argument's binding may be followed there, which undoing the
        trail does not reverse, so the later clauses and the choicepoint must see the
        argument as called.
        """
        if i == 0 or self.next_start is None or type(p) is Slot and p.i not in self.known:
            return f"a{i}"
        local = self.temp()
        self.emit(f"{local} = a{i}", 1)
        return local

    def state(self) -> bool | None:
        return self.committed

    def restore(self, state: bool | None) -> None:
        self.committed = state

    def cut(self) -> None:
        # No choicepoint was made since the clause began: committing means pushing none
        # for the later clauses, and failing from here on fails the whole call.
        self.committed = True
        self.fail = "return False"

    def alternatives(self) -> None:
        """Emit the choicepoint for the branch's later clauses, unless cut."""
        if self.committed or self.alt_start is None:
            return
        state = f"[{PROC}, mark, ({self.names}), nxt, proc, {self.alt_start}]"
        self.emit(f"cps.append({state})", 1)

    def exit(self, cont: str) -> None:
        self.alternatives()
        self.emit(f"return {cont}", 1)

    def self_call(self, args: str) -> None:
        self.alternatives()
        self.emit(f"{self.names}= {args}", 1)
        self.emit("steps += 1", 1)
        self.emit(f"if steps >= {PROC_LOOPS}: return [{self.names}None]", 1)
        if self.next_start is None:
            self.emit("start = 0; continue", 1)
        else:
            self.emit("start = -1; break", 1)
