"""Compile a stored clause into a specialised Python function (our own code generation).

The generic path walks head templates recursively and builds every body goal through
`build`; for a clause that runs often that costs most of an inference. The generated
function does the same work in straight-line code: it unifies each head argument with the
shape it expects (binding in write mode when the call argument is unbound, reading the
subterms in read mode), runs a leading cut and leading arithmetic (`is/2`, comparisons)
and `=/2` inline, and returns the continuation with the remaining body goals:

    run(args, trail, cb, nxt, cps) -> continuation, or False when the clause fails

A clause whose whole remaining body is a call to its own predicate returns that call's
arguments as a `list` instead, and the machine loops on the predicate without building
the goal term or a continuation cell (the common shape of a deterministic recursion).

Constants are passed to a factory instead of being written into the source, so clauses
of the same shape (for example 100,000 `fact(N, vN)` facts) share one compiled factory.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from robocram.logic.choicepoints import ChoicePoint, Cont
from robocram.logic.direct_calls import direct_callee
from robocram.logic.early_guards import guard_goals, rejection
from robocram.logic.goal_writer import (
    FACTORY_CACHE_SIZE,
    GoalWriter,
    deref_line,
    inlinable,
    inline_function,
    make_factory,
    slots_in,
    term_parts,
)
from robocram.logic.inline_calls import CalleeTable, Lookup, expand_call, max_slot
from robocram.logic.keys import pred_key
from robocram.logic.template import Slot, Tmpl
from robocram.logic.terms import Var
from robocram.logic.value import Value

__all__ = [
    "FACTORY_CACHE_SIZE",
    "Bound",
    "ClauseCode",
    "ClauseFn",
    "ClauseWriter",
    "compile_clause_fn",
    "make_factory",
]


class ClauseCode(Protocol):
    """What code generation reads from a stored clause (see clause.Clause)."""

    head: tuple[Value, ...]
    body_rev: tuple[Value, ...]
    name: str


# A constant bound per knowledge base: "table" (it), "generation" (its generation when
# compiled), "scan" (the predicate's Scan) or the number of a directly called procedure.
Bound = str | int
ClauseFn = Callable[[tuple[Value, ...], list[Var], int, Cont, list[ChoicePoint]], Cont]

_INLINE_DEPTH = 2  # calls compiled into calls compiled in: each doubles the rest's code
_CONTROL = {(",", 2), (";", 2), ("->", 2), ("*->", 2), ("\\+", 1)}


def compile_clause_fn(clause: ClauseCode) -> ClauseFn:
    """Return the specialised function for `clause` (factories are cached by source)."""
    gen = ClauseWriter()
    source = gen.clause_source(clause)
    return make_factory(source)(*gen.consts)


def _arg_names(arity: int) -> str:
    """`a0, a1, ` : the locals holding the call's arguments (a tuple target)."""
    return "".join(f"a{i}, " for i in range(arity))


def _is_self_call(goal: Value, clause: ClauseCode) -> bool:
    """True when `goal` calls the clause's own predicate (same name and arity)."""
    parts = term_parts(goal)
    return parts is not None and parts[0] == clause.name and len(parts[1]) == len(clause.head)


def _conjuncts(g: Value) -> list[Value]:
    """The goals of a conjunction `(A, B, ...)`, in order."""
    parts = term_parts(g)
    if parts is not None and parts[0] == "," and len(parts[1]) == 2:
        return [*_conjuncts(parts[1][0]), *_conjuncts(parts[1][1])]
    return [g]


def _is_true(g: Value) -> bool:
    return type(g) is str and g == "true"


class ClauseWriter(GoalWriter):
    """Emits the Python source of a clause: head, leading inline goals, continuation."""

    callees: CalleeTable | None = None  # a procedure's: calls to inline (see inline_call)
    next_slot = 0  # the first slot number no goal of the clause uses
    inlined = 0  # calls compiled in around the goal being written
    direct = False  # a leading call of a compiled procedure made here (see direct_call)
    level = 0  # 0 without direct calls, else one more than the callees' highest level
    # What the code asked of `callees` and which constants are the knowledge base's own
    # (see shared_code.py); None when not recorded.
    seen: list[Lookup] | None = None
    bound: list[tuple[int, Bound]] | None = None
    directs = 0  # procedures called directly so far

    def bound_const(self, value: Value, mark: Bound) -> str:
        """A constant that is the knowledge base's own (see `Bound`); noted in `bound`."""
        name = self.const(value)
        if self.bound is not None:
            self.bound.append((len(self.consts) - 1, mark))
        return name

    def clause_source(self, clause: ClauseCode) -> str:
        """Generate `make(k0, k1, ...)` returning the clause function."""
        arity = len(clause.head)
        if arity:
            self.emit(f"{_arg_names(arity)} = args", 1)
        self.clause_code(clause)
        params = ", ".join(f"k{i}" for i in range(len(self.consts)))
        return "\n".join(
            [f"def make({params}):", "  def run(args, trail, cb, nxt, cps):", *self.lines]
            + ["  return run", ""]
        )

    def clause_code(
        self, clause: ClauseCode, switched: bool = False, arity_known: bool = True
    ) -> None:
        """Emit head unification, the inline built-ins and the exit of one clause.

        `switched`: the first argument is dereferenced and already known to have the
        head's functor or constant (a procedure switched on it): only its subterms are
        unified; unless `arity_known`, the unpacking of them checks the arity (the switch
        compared the name only).
        """
        self.known = set()
        self.dereffed = set()
        body = list(reversed(clause.body_rev))
        self.next_slot = max_slot([*clause.head, *body])
        early = [r for r in map(rejection, guard_goals(body)) if r is not None]
        for i, p in enumerate(clause.head):
            if i == 0 and switched and type(p) is Tmpl:
                self.read_args(p.args, "a0[1]", 1, checked=arity_known)
            elif not (i == 0 and switched and type(p) in (str, int)):
                self.unify_arg(p, self.arg_local(i, p), 1)
            if early and any(type(q) is Tmpl for q in clause.head[i + 1 :]):
                early = self.reject_early(early)
        self.body_code(clause, body)

    def reject_early(self, guards: list[tuple[list[int], str]]) -> list[tuple[list[int], str]]:
        """Emit the guards whose values are all known (see early_guards); return the rest."""
        later = []
        for slots, condition in guards:
            if any(i not in self.known for i in slots):
                later.append((slots, condition))
                continue
            for i in slots:
                if i not in self.dereffed:
                    self.emit(deref_line(f"v{i}"), 1)
            self.emit(f"if {condition}: {self.fail}", 1)
        return later

    def arg_local(self, i: int, p: Value) -> str:
        """The local to unify head argument `i` (template `p`) with; unify_arg derefs it."""
        return f"a{i}"

    def body_code(self, clause: ClauseCode, body: list[Value]) -> None:
        """Emit the leading inline goals of `body`, then its exit."""
        while body and self.inline_goal(body[0]):
            body.pop(0)
        if body and self.inline_if(clause, body):
            return
        if body and self.inline_call(clause, body):
            return
        held = set(self.known)  # the slots that hold a value before the continuation
        self.fresh(body, 1)
        if len(body) == 1 and _is_self_call(body[0], clause):
            args = "".join(f"{self.build(a)}, " for a in term_parts(body[0])[1])  # type: ignore[index]
            self.self_call(args)
            return
        self.direct_call(clause, body, held)
        cont = "nxt"
        for g in reversed(self.goals(body, held)):
            cont = f"({g}, cb, {cont})"
        self.exit(cont)

    def direct_call(self, clause: ClauseCode, body: list[Value], held: set[int]) -> None:
        """A leading call of a compiled procedure of a low level: while the knowledge base
        is as it was, call it here with the rest of the body as its continuation (see
        direct_calls.py)."""
        if not body or not self.direct or self.callees is None or inlinable(body[0]):
            return
        found = direct_callee(self.callees, body[0], (clause.name, len(clause.head)), self.seen)
        if found is None:
            return
        generation, proc, level = found
        self.level = max(self.level, level + 1)
        name, args = term_parts(body[0])  # type: ignore[misc]
        inner = "".join(f"{self.build(a)}, " for a in args)
        held = held | set(slots_in(body[0], []))
        rest = "nxt"
        for g in reversed(self.goals(body[1:], held)):
            rest = f"({g}, cb, {rest})"
        table = self.bound_const(self.callees, "table")
        self.emit(f"if {table}._generation == {self.bound_const(generation, 'generation')}:", 1)
        self.base += 1
        self.alternatives()
        self.emit(f"dn = {rest}", 1)
        callee = self.bound_const(proc, self.directs)  # the knowledge base's: bound per KB
        self.directs += 1
        self.emit(f"dr = {callee}(({inner}), trail, dn, cps, 0)", 1)
        # handed back (see procedure.py): the call goes to the machine, as it would have
        key = self.const(pred_key(name, len(args)))
        self.emit(f"if type(dr) is list: dr = (({key}, tuple(dr[:-1]), CALL), cb, dn)", 1)
        self.emit("return dr", 1)
        self.base -= 1

    def alternatives(self) -> None:
        """Emit what must precede leaving the clause (a procedure's choicepoint)."""

    def self_call(self, args: str) -> None:
        """Exit by a call to the clause's own predicate: return its argument list.

        The machine loops on the predicate without building the goal term or a
        continuation cell (the common shape of a deterministic recursion).
        """
        self.emit(f"return [{args}]", 1)

    def exit(self, cont: str) -> None:
        """Exit with the continuation expression `cont` (the remaining body goals)."""
        self.emit(f"return {cont}", 1)

    def goal(self, g: Value) -> str:
        """Python expression building body goal `g`; control constructs goal by goal.

        A test, `is/2` or `=/2` becomes an inline goal (see inline_goal.py), so that the
        machine runs Python code instead of looking up and walking the built-in.
        """
        run = self.inline_run([g]) if inlinable(g) else None
        if run is not None:
            return run
        parts = term_parts(g)
        if parts is None:
            return self.build(g)
        name, args = parts
        if (name, len(args)) in _CONTROL:
            compiled = self.control(name, args)
            if compiled is not None:
                return compiled
            inner = "".join(f"{self.goal(a)}, " for a in args)
            return f"mkt(({self.const(name)}, ({inner})))"
        if type(g) is Tmpl:  # a call: a plain tuple the machine recognises by CALL
            inner = "".join(f"{self.build(a)}, " for a in args)
            return f"({self.const(pred_key(name, len(args)))}, ({inner}), CALL)"
        return self.build(g)

    def control(self, name: str, args: tuple[Value, ...]) -> str | None:
        """A conjunction, disjunction, if-then(-else) or negation as a marked goal tuple (see
        inline_goal.py), so the machine runs it without looking up the construct; None
        for the others, and for `(X ; B)` with X a variable, which stays a term so that X
        bound to `(C -> T)` at run time still reads as an if-then-else.
        """
        if name == ",":
            return self.sequence(*args)
        if name == "->":
            return f"({self.sequence(args[0])}, {self.then(args[1])}, IFTHEN)"
        if name == "\\+":
            return f"({self.sequence(args[0])}, None, NOT)"
        if name != ";" or type(args[0]) is Slot:
            return None
        left = term_parts(args[0])
        right = self.sequence(args[1])
        if left is not None and len(left[1]) == 2 and left[0] in ("->", "*->"):
            if left[0] == "*->":
                return None
            cond, then = self.sequence(left[1][0]), self.then(left[1][1])
            return f"({cond}, ({then}, {right}), ITE)"
        return f"({self.sequence(args[0])}, {right}, DISJ)"

    def then(self, goal: Value) -> str:
        """The then-branch of an if-then(-else): None when it is `true` (the machine goes
        straight on after the condition's cut, with no goal to run)."""
        return "None" if all(_is_true(g) for g in _conjuncts(goal)) else self.sequence(goal)

    def sequence(self, *parts: Value) -> str:
        """One goal running the conjunction of `parts`: its goal, or a SEQ of its goals."""
        exprs = self.goals([g for part in parts for g in _conjuncts(part)])
        out = exprs[-1]
        for e in reversed(exprs[:-1]):  # (first, rest, SEQ), the rest nested the same way
            out = f"({e}, {out}, SEQ)"
        return out

    def goals(self, body: list[Value], held: set[int] | None = None) -> list[str]:
        """Expressions of the continuation's goals: each run of inline goals is one goal.

        `held`: the slots holding a value before `body` runs (the others are new
        variables); a run of inline goals may bind one that no goal before it names
        without unifying (see inline_function).
        """
        body = [g for g in body if not _is_true(g)] or body  # `true` does nothing
        out: list[str] = []
        used = set(held) if held is not None else None
        i = 0
        while i < len(body):
            j = i
            while j < len(body) and inlinable(body[j]):
                j += 1
            run = self.inline_run(body[i:j], used) if j > i else None
            if run is not None:
                out.append(run)
                step = j - i
            else:
                out.append(self.goal(body[i]) if j == i else self.build(body[i]))
                step = 1
            if used is not None:
                for g in body[i : i + step]:
                    used.update(slots_in(g, []))
            i += step
        return out

    def inline_run(self, goals: list[Value], used: set[int] | None = None) -> str | None:
        """Expression of one inline goal running `goals` (their slots all hold values).

        `used`: the slots that may be bound or shared when the run starts; None when
        that is not known.
        """
        slots: list[int] = []
        for g in goals:
            slots_in(g, slots)
        unbound = set() if used is None else {i for i in slots if i not in used}
        fn = inline_function(goals, slots, unbound)
        if fn is None:
            return None
        values = "".join(f"v{i}, " for i in slots)
        return f"({self.const(fn)}, ({values}), INLINE)"

    def inline_if(self, clause: ClauseCode, body: list[Value]) -> bool:
        """`(Cond -> Then ; Else)` first in `body`, Cond a test: a Python `if` instead.

        Each branch continues with its goals and the rest of the body, so no choicepoint
        or control goal is made; a cut in either branch cuts the clause, as it would.
        """
        parts = term_parts(body[0])
        if parts is None or len(parts[1]) != 2 or parts[0] not in (";", "->"):
            return False
        cond_then, other = (parts[1][0], parts[1][1]) if parts[0] == ";" else (body[0], "fail")
        inner = term_parts(cond_then)
        if inner is None or inner[0] != "->" or len(inner[1]) != 2:
            return False
        test = self.test(inner[1][0])
        if test is None:
            return False
        saved = (set(self.known), set(self.dereffed), self.fail, self.base, self.state())
        for branch, goals in ((f"if {test}:", inner[1][1]), ("else:", other)):
            self.emit(branch, 1)
            self.base += 1
            self.body_code(clause, [*_conjuncts(goals), *body[1:]])
            self.known, self.dereffed, self.fail, self.base = (
                set(saved[0]),
                set(saved[1]),
                *saved[2:4],
            )
            self.restore(saved[4])
        return True

    def inline_call(self, clause: ClauseCode, body: list[Value]) -> bool:
        """A call of a small one-clause predicate first in `body`: its goals in its place
        (see inline_calls.py), while the knowledge base is as it was; else the call."""
        if self.callees is None or self.inlined >= _INLINE_DEPTH:
            return False
        own = (clause.name, len(clause.head))
        found = expand_call(self.callees, body[0], self.next_slot, own, self.seen)
        if found is None:
            return False
        generation, goals, used = found
        self.next_slot += used
        saved = (set(self.known), set(self.dereffed), self.fail, self.base, self.state())
        table = self.bound_const(self.callees, "table")
        # a constant, not a literal: the same source at every generation (one factory)
        self.emit(f"if {table}._generation == {self.bound_const(generation, 'generation')}:", 1)
        for branch in ("inline", "call"):
            if branch == "call":
                self.emit("else:", 1)
            self.base += 1
            if branch == "inline":
                self.inlined += 1
                self.body_code(clause, [*goals, *body[1:]])
                self.inlined -= 1
            else:
                callees, self.callees = self.callees, None  # the call itself, not again
                self.body_code(clause, body)
                self.callees = callees
            self.known, self.dereffed = set(saved[0]), set(saved[1])
            self.fail, self.base = saved[2], saved[3]
            self.restore(saved[4])
        return True

    def state(self) -> bool | None:
        """What a branch of an inline if-then-else may change besides the slots."""
        return None

    def restore(self, state: bool | None) -> None:
        """Undo a branch's changes to `state()`."""
