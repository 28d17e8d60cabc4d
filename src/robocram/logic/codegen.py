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
from typing import Any, Protocol

from robocram.logic.arith import BINARY_FUNCTIONS, apply_binary, evaluate
from robocram.logic.early_guards import guard_goals, rejection
from robocram.logic.inline_goal import InlineGoal
from robocram.logic.lru import LRUCache
from robocram.logic.template import Slot, Tmpl
from robocram.logic.terms import Term, Var, new_term
from robocram.logic.unify import identical, unify
from robocram.logic.univ import univ_compose, univ_list

__all__ = [
    "FACTORY_CACHE_SIZE",
    "ClauseCode",
    "ClauseFn",
    "ClauseWriter",
    "compile_clause_fn",
    "make_factory",
]


class ClauseCode(Protocol):
    """What code generation reads from a stored clause (see clause.Clause)."""

    head: tuple[Any, ...]
    body_rev: tuple[Any, ...]
    name: str


ClauseFn = Callable[[tuple[Any, ...], list[Var], int, Any, list[list[Any]]], Any]

_NAMESPACE: dict[str, Any] = {
    "Var": Var,
    "Term": Term,
    "InlineGoal": InlineGoal,
    "univ_list": univ_list,
    "univ_compose": univ_compose,
    "new_term": new_term,
    "unify": unify,
    "identical": identical,
    "ev": evaluate,
    "ap2": apply_binary,
}
# Generated factories are pure functions of their source text (constants are parameters),
# so one bounded memo serves every knowledge base without sharing any resolved state.
FACTORY_CACHE_SIZE = 4096
_FACTORIES: LRUCache[str, Callable[..., Any]] = LRUCache(FACTORY_CACHE_SIZE)
_ARITH_OPS = {"+": "+", "-": "-", "*": "*"}
_COMPARE_OPS = {"<": "<", ">": ">", "=<": "<=", ">=": ">=", "=:=": "==", "=\\=": "!="}
_EXACT_TYPES = (str, int, float)
# ISO type tests inlined at the head of a clause body: the condition on the dereferenced value
_TYPE_TESTS = {
    "var": "type({0}) is Var",
    "nonvar": "type({0}) is not Var",
    "atom": "type({0}) is str",
    "number": "type({0}) is int or type({0}) is float",
    "integer": "type({0}) is int",
    "float": "type({0}) is float",
    "atomic": "type({0}) is not Var and type({0}) is not Term",
    "compound": "type({0}) is Term",
    "callable": "type({0}) is str or type({0}) is Term",
}
_CONTROL = {(",", 2), (";", 2), ("->", 2), ("*->", 2), ("\\+", 1)}


def compile_clause_fn(clause: ClauseCode) -> ClauseFn:
    """Return the specialised function for `clause` (factories are cached by source)."""
    gen = ClauseWriter()
    source = gen.clause_source(clause)
    return make_factory(source)(*gen.consts)


def make_factory(source: str) -> Callable[..., Any]:
    """Execute generated source defining `make(...)`, once per distinct source text."""
    factory = _FACTORIES.get(source)
    if factory is None:
        namespace = dict(_NAMESPACE)
        exec(compile(source, "<robocram clause>", "exec"), namespace)  # noqa: S102
        factory = namespace["make"]
        _FACTORIES.put(source, factory)
    return factory


def deref_line(x: str) -> str:
    """The statement dereferencing local `x` in place."""
    return f"while type({x}) is Var and {x}.ref is not None: {x} = {x}.ref"


def _slots_in(t: Any, out: list[int]) -> list[int]:
    """Collect the slot numbers in a template, in order of first appearance."""
    if type(t) is Slot:
        if t.i not in out:
            out.append(t.i)
    elif type(t) is Tmpl:
        for a in t.args:
            _slots_in(a, out)
    return out


def _arg_names(arity: int) -> str:
    """`a0, a1, ` : the locals holding the call's arguments (a tuple target)."""
    return "".join(f"a{i}, " for i in range(arity))


def _parts(t: Any) -> tuple[str, tuple[Any, ...]] | None:
    """Name and arguments of a compound term or template; None for anything else."""
    if type(t) is Tmpl:
        return t.name, t.args
    if type(t) is Term:
        return t[0], t[1]
    return None


def _is_self_call(goal: Any, clause: ClauseCode) -> bool:
    """True when `goal` calls the clause's own predicate (same name and arity)."""
    parts = _parts(goal)
    return parts is not None and parts[0] == clause.name and len(parts[1]) == len(clause.head)


def _conjuncts(g: Any) -> list[Any]:
    """The goals of a conjunction `(A, B, ...)`, in order."""
    parts = _parts(g)
    if parts is not None and parts[0] == "," and len(parts[1]) == 2:
        return [*_conjuncts(parts[1][0]), *_conjuncts(parts[1][1])]
    return [g]


def _inlinable(g: Any) -> bool:
    """True for a goal that runs inline once its slots hold values (tests, is/2, =/2)."""
    parts = _parts(g)
    if parts is None:
        return g == "true"
    name, args = parts
    if len(args) == 1:
        return name in _TYPE_TESTS
    if name == "=.." and len(args) == 2:
        return type(args[0]) is Slot
    return len(args) == 2 and (name in _COMPARE_OPS or name in _INLINE_BINARY)


_INLINE_BINARY = frozenset(["is", "=", "==", "\\=="])


def inline_function(goals: list[Any], slots: list[int]) -> Any:
    """Compile inline goals to `fn(trail, *values of slots)`: true when all succeed.

    None when one of them cannot run inline after all.
    """
    writer = ClauseWriter()
    writer.known = set(slots)
    for g in goals:
        if not writer.inline_goal(g):
            return None
    params = ", ".join(f"k{i}" for i in range(len(writer.consts)))
    values = "".join(f", v{i}" for i in slots)
    head = [f"def make({params}):", f"  def fn(trail{values}):"]
    source = "\n".join([*head, *writer.lines, "    return True", "  return fn", ""])
    return make_factory(source)(*writer.consts)


class ClauseWriter:
    """Emits the Python source of clause code, tracking which slots hold values."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.consts: list[Any] = []
        self.known: set[int] = set()
        self.dereffed: set[int] = set()
        self.temps = 0
        self.base = 0
        self.fail = "return False"  # the statement a failing head or inline goal runs

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

    def clause_code(self, clause: ClauseCode, switched: bool = False) -> None:
        """Emit head unification, the inline built-ins and the exit of one clause.

        `switched`: the first argument is dereferenced and already known to have the
        head's functor or constant (a procedure switched on it): only its subterms are
        unified.
        """
        self.known = set()
        self.dereffed = set()
        body = list(reversed(clause.body_rev))
        early = [r for r in map(rejection, guard_goals(body)) if r is not None]
        for i, p in enumerate(clause.head):
            if i == 0 and switched and type(p) is Tmpl:
                self.read_args(p.args, "a0[1]", 1)
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

    def arg_local(self, i: int, p: Any) -> str:
        """The local to unify head argument `i` (template `p`) with; unify_arg derefs it."""
        return f"a{i}"

    def body_code(self, clause: ClauseCode, body: list[Any]) -> None:
        """Emit the leading inline goals of `body`, then its exit."""
        while body and self.inline_goal(body[0]):
            body.pop(0)
        if body and self.inline_if(clause, body):
            return
        self.fresh(body, 1)
        if len(body) == 1 and _is_self_call(body[0], clause):
            args = "".join(f"{self.build(a)}, " for a in _parts(body[0])[1])  # type: ignore[index]
            self.self_call(args)
            return
        cont = "nxt"
        for g in reversed(self.goals(body)):
            cont = f"({g}, cb, {cont})"
        self.exit(cont)

    def self_call(self, args: str) -> None:
        """Exit by a call to the clause's own predicate: return its argument list.

        The machine loops on the predicate without building the goal term or a
        continuation cell (the common shape of a deterministic recursion).
        """
        self.emit(f"return [{args}]", 1)

    def exit(self, cont: str) -> None:
        """Exit with the continuation expression `cont` (the remaining body goals)."""
        self.emit(f"return {cont}", 1)

    def cut(self) -> None:
        """Emit a cut at the neck: drop the choicepoints made since the clause began."""
        self.emit("del cps[cb:]", 1)

    def emit(self, line: str, depth: int) -> None:
        self.lines.append("  " * (depth + self.base + 1) + line)

    def const(self, value: Any) -> str:
        self.consts.append(value)
        return f"k{len(self.consts) - 1}"

    def temp(self) -> str:
        self.temps += 1
        return f"t{self.temps}"

    def fresh(self, templates: list[Any], depth: int) -> None:
        """Give each slot not yet holding a value a new unbound variable."""
        found: list[int] = []
        for t in templates:
            _slots_in(t, found)
        for i in found:
            if i not in self.known:
                self.emit(f"v{i} = Var()", depth)
                self.known.add(i)

    def build(self, t: Any) -> str:
        """Python expression building template `t` (all its slots must be known)."""
        if type(t) is Slot:
            return f"v{t.i}"
        if type(t) is Tmpl:
            args = "".join(f"{self.build(a)}, " for a in t.args)
            return f"new_term(Term, ({self.const(t.name)}, ({args})))"
        return self.const(t)

    def goal(self, g: Any) -> str:
        """Python expression building body goal `g`; control constructs goal by goal.

        A test, `is/2` or `=/2` becomes an `InlineGoal` (see inline_goal.py), so that the
        machine runs Python code instead of looking up and walking the built-in.
        """
        run = self.inline_run([g]) if _inlinable(g) else None
        if run is not None:
            return run
        parts = _parts(g)
        if parts is None:
            return self.build(g)
        name, args = parts
        if (name, len(args)) in _CONTROL:
            inner = "".join(f"{self.goal(a)}, " for a in args)
            return f"new_term(Term, ({self.const(name)}, ({inner})))"
        return self.build(g)

    def goals(self, body: list[Any]) -> list[str]:
        """Expressions of the continuation's goals: each run of inline goals is one goal."""
        out: list[str] = []
        i = 0
        while i < len(body):
            j = i
            while j < len(body) and _inlinable(body[j]):
                j += 1
            run = self.inline_run(body[i:j]) if j > i else None
            if run is not None:
                out.append(run)
                i = j
            else:
                out.append(self.goal(body[i]) if j == i else self.build(body[i]))
                i += 1
        return out

    def inline_run(self, goals: list[Any]) -> str | None:
        """Expression of one InlineGoal running `goals` (their slots all hold values)."""
        slots: list[int] = []
        for g in goals:
            _slots_in(g, slots)
        fn = inline_function(goals, slots)
        if fn is None:
            return None
        values = "".join(f"v{i}, " for i in slots)
        return f"new_term(InlineGoal, ({self.const(fn)}, ({values})))"

    def unify_arg(self, p: Any, x: str, depth: int) -> None:
        """Emit code unifying template `p` with the (un-dereferenced) value in local `x`."""
        if type(p) is Slot:
            if p.i in self.known:
                self.unify_locals(f"v{p.i}", x, depth)
                self.dereffed.discard(p.i)
            else:
                self.emit(f"v{p.i} = {x}", depth)
                self.known.add(p.i)
            return
        if type(p) is not Tmpl and type(p) not in _EXACT_TYPES:
            self.emit(f"if not unify({self.const(p)}, {x}, trail): {self.fail}", depth)
            return
        self.emit(deref_line(x), depth)
        if type(p) is not Tmpl:
            k = self.const(p)
            self.emit(f"if type({x}) is Var: {x}.ref = {k}; trail.append({x})", depth)
            self.emit(f"elif type({x}) is not {type(p).__name__} or {x} != {k}: {self.fail}", depth)
            return
        before = set(self.known)
        self.emit(f"if type({x}) is Var:", depth)
        self.fresh([p], depth + 1)
        self.emit(f"{x}.ref = {self.build(p)}; trail.append({x})", depth + 1)
        self.known = before
        name = self.const(p.name)
        n = len(p.args)
        self.emit(f"elif type({x}) is Term and {x}[0] == {name} and len({x}[1]) == {n}:", depth)
        self.read_args(p.args, f"{x}[1]", depth + 1)
        self.emit(f"else: {self.fail}", depth)

    def unify_locals(self, a: str, b: str, depth: int) -> None:
        """Emit unification of the values in locals `a` and `b` (both dereferenced in place).

        Binding an unbound side is done here; only two non-variables call `unify`.
        """
        self.emit(deref_line(a), depth)
        self.emit(deref_line(b), depth)
        self.emit(f"if {a} is not {b}:", depth)
        self.emit(f"if type({a}) is Var: {a}.ref = {b}; trail.append({a})", depth + 1)
        self.emit(f"elif type({b}) is Var: {b}.ref = {a}; trail.append({b})", depth + 1)
        self.emit(f"elif not unify({a}, {b}, trail): {self.fail}", depth + 1)

    def read_args(self, pargs: tuple[Any, ...], src: str, depth: int) -> None:
        """Read mode: unpack the call's subterms, then unify each with its template."""
        names: list[str] = []
        later: list[tuple[Any, str]] = []
        for a in pargs:
            if type(a) is Slot and a.i not in self.known:
                names.append(f"v{a.i}")
                self.known.add(a.i)
            else:
                t = self.temp()
                names.append(t)
                later.append((a, t))
        self.emit(f"{''.join(n + ', ' for n in names)}= {src}", depth)
        for a, t in later:
            self.unify_arg(a, t, depth)

    def inline_goal(self, g: Any) -> bool:
        """Emit a leading deterministic built-in inline; False when `g` is not one."""
        if g == "!":
            self.cut()
            return True
        if g == "true":
            return True
        parts = _parts(g)
        if parts is not None and len(parts[1]) == 1 and parts[0] in _TYPE_TESTS:
            return self.type_test(parts[0], parts[1][0])
        if parts is not None and len(parts[1]) == 2 and parts[0] in ("==", "\\=="):
            test = self.test(g)
            if test is not None:
                self.emit(f"if not ({test}): {self.fail}", 1)
            return test is not None
        if parts is None or len(parts[1]) != 2:
            return False
        name, (left, right) = parts
        if name in _COMPARE_OPS:
            a, b = self.expr(left), self.expr(right)
            if a is None or b is None:
                return False
            self.emit(f"if not ({a} {_COMPARE_OPS[name]} {b}): {self.fail}", 1)
            return True
        if name == "is":
            value = self.expr(right)
            if value is None:
                return False
            self.assign_or_unify(left, value)
            return True
        if name == "=..":
            return self.univ(left, right)
        if name == "=":
            if type(right) is Slot and right.i not in self.known:
                left, right = right, left
            if type(left) is Slot and left.i not in self.known:
                if left.i in _slots_in(right, []):
                    return False
                self.fresh([right], 1)
                self.emit(f"v{left.i} = {self.build(right)}", 1)
                self.known.add(left.i)
                return True
            if type(right) is Slot:
                left, right = right, left
            if type(left) is Slot:  # a value against a template: head-style read/write code
                self.unify_arg(right, f"v{left.i}", 1)
                self.dereffed.discard(left.i)
                return True
            self.fresh([left, right], 1)
            left_code, right_code = self.build(left), self.build(right)
            self.emit(f"if not unify({left_code}, {right_code}, trail): {self.fail}", 1)
            return True
        return False

    def univ(self, term: Any, items: Any) -> bool:
        """Emit `Term =.. Items` for a slot `Term`: taken apart, or built when unbound."""
        if type(term) is not Slot or term.i in _slots_in(items, []):
            return False
        v = f"v{term.i}"
        if term.i not in self.known:
            self.fresh([items], 1)
            self.emit(f"{v} = univ_compose({self.build(items)})", 1)
            self.known.add(term.i)
            return True
        parts = self.temp()
        self.emit(f"{parts} = univ_list({v})", 1)
        self.emit(f"if {parts} is None:", 1)
        known, dereffed = set(self.known), set(self.dereffed)
        self.fresh([items], 2)
        built = self.temp()
        self.emit(f"{built} = univ_compose({self.build(items)})", 2)
        self.unify_locals(v, built, 2)
        self.known = known
        self.emit("else:", 1)
        self.unify_arg(items, parts, 2)
        self.dereffed = dereffed - {term.i, *_slots_in(items, [])}
        return True

    def inline_if(self, clause: ClauseCode, body: list[Any]) -> bool:
        """`(Cond -> Then ; Else)` first in `body`, Cond a test: a Python `if` instead.

        Each branch continues with its goals and the rest of the body, so no choicepoint
        or control goal is made; a cut in either branch cuts the clause, as it would.
        """
        parts = _parts(body[0])
        if parts is None or len(parts[1]) != 2 or parts[0] not in (";", "->"):
            return False
        cond_then, other = (parts[1][0], parts[1][1]) if parts[0] == ";" else (body[0], "fail")
        inner = _parts(cond_then)
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

    def state(self) -> Any:
        """What a branch of an inline if-then-else may change besides the slots."""
        return None

    def restore(self, state: Any) -> None:
        """Undo a branch's changes to `state()`."""

    def test(self, g: Any) -> str | None:
        """A Python condition for test goal `g` (type tests, comparisons, `\\+`, `,`)."""
        if g in ("true", "fail", "false"):
            return "True" if g == "true" else "False"
        parts = _parts(g)
        if parts is None:
            return None
        name, args = parts
        if name == "," and len(args) == 2 or name == "\\+" and len(args) == 1:
            tests = [self.test(a) for a in args]
            if None in tests:
                return None
            return f"not ({tests[0]})" if name == "\\+" else f"({tests[0]}) and ({tests[1]})"
        if len(args) == 1 and name in _TYPE_TESTS:
            slot = args[0]
            if type(slot) is not Slot or slot.i not in self.known:
                return None
            self.deref_slot(slot.i)
            return _TYPE_TESTS[name].format(f"v{slot.i}")
        if len(args) == 2 and name in _COMPARE_OPS:
            a, b = self.expr(args[0]), self.expr(args[1])
            return None if a is None or b is None else f"{a} {_COMPARE_OPS[name]} {b}"
        if len(args) == 2 and name in ("==", "\\=="):
            if any(i not in self.known for i in _slots_in(g, [])):
                return None
            same = f"identical({self.build(args[0])}, {self.build(args[1])})"
            return same if name == "==" else f"not {same}"
        return None

    def deref_slot(self, i: int) -> None:
        """Dereference slot `i` in place, once."""
        if i not in self.dereffed:
            self.emit(deref_line(f"v{i}"), 1)
            self.dereffed.add(i)

    def type_test(self, name: str, arg: Any) -> bool:
        """Emit a type test (`number(X)`, `var(X)`, ...) of a slot holding a value."""
        if type(arg) is not Slot or arg.i not in self.known:
            return False
        self.deref_slot(arg.i)
        self.emit(f"if not ({_TYPE_TESTS[name].format(f'v{arg.i}')}): {self.fail}", 1)
        return True

    def assign_or_unify(self, target: Any, value: str) -> None:
        """Bind a fresh slot to `value` directly, or unify `target` with it."""
        if type(target) is Slot and target.i not in self.known:
            self.emit(f"v{target.i} = {value}", 1)
            self.known.add(target.i)
            self.dereffed.add(target.i)  # a number
            return
        result = self.temp()
        self.emit(f"{result} = {value}", 1)
        self.unify_arg(target, result, 1)

    def expr(self, t: Any) -> str | None:
        """Python expression evaluating arithmetic template `t`; None if a slot is unset."""
        if type(t) is Slot:
            if t.i not in self.known:
                return None
            v = f"v{t.i}"
            if t.i not in self.dereffed:
                # A slot read from a call argument is often a bound variable: dereference
                # it once so every later use takes the int fast path.
                self.emit(deref_line(v), 1)
                self.dereffed.add(t.i)
            return f"({v} if type({v}) is int else ev({v}))"
        if type(t) is int:
            return self.const(t)
        parts = _parts(t)
        if parts is not None:
            name, args = parts
            if len(args) == 2 and name in BINARY_FUNCTIONS:
                a, b = self.expr(args[0]), self.expr(args[1])
                if a is None or b is None:
                    return None
                if name in _ARITH_OPS:
                    return f"({a} {_ARITH_OPS[name]} {b})"
                return f"ap2({self.const(name)}, {a}, {b})"
            if any(i not in self.known for i in _slots_in(t, [])):
                return None
        return f"ev({self.build(t)})"
