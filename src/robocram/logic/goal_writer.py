"""Emit the Python code of goals that run inline: head unification, tests, arithmetic.

`GoalWriter` tracks which clause variables (slots) hold values and which are already
dereferenced, and writes straight-line code for unifying a value with a template (read
mode when the value is bound, write mode when it is a variable), ISO type tests,
comparisons, `is/2`, `=/2`, `==/2` and `=../2`. `codegen.ClauseWriter` builds whole
clauses on it, `procedure.py` whole predicates, and `inline_function` the runs of such
goals that follow a call (see inline_goal.py). Generated sources become functions
through `make_factory` (a clause's and an inline run's constants are closure cells, its
code shared by every clause of its shape) or `function_factory` (a procedure's constants
are its globals: see function_factory.py), memoised by source text (and their code kept
on disk: `code_cache`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from robocram.logic.arith import BINARY_FUNCTIONS, apply_binary, evaluate
from robocram.logic.arith_inline import INT_FAST, int_fast
from robocram.logic.code_cache import compiled
from robocram.logic.function_factory import FunctionFactory
from robocram.logic.functor_arg import arg_check, fresh_vars, functor_make
from robocram.logic.goal_terms import TERM_GOALS, emit_term_goal
from robocram.logic.inline_goal import CALL, DISJ, IFTHEN, INLINE, ITE, NOT, SEQ
from robocram.logic.lru import LRUCache
from robocram.logic.template import Slot, Tmpl
from robocram.logic.terms import Term, Var, make_term, make_var
from robocram.logic.unify import identical, unify
from robocram.logic.univ import univ_compose, univ_list
from robocram.logic.value import Value

__all__ = [
    "FACTORY_CACHE_SIZE",
    "GoalWriter",
    "deref_line",
    "function_factory",
    "inlinable",
    "inline_function",
    "make_factory",
    "term_parts",
    "slots_in",
]

# A generated `make(constants...)`: it returns a ClauseFn, a Procedure or an inline goal
# function, as its source says. mypy cannot read generated source, so the result is Any.
Factory = Callable[..., Any]

_NAMESPACE: dict[str, object] = {
    "Var": Var,
    "newv": make_var,  # `newv()` then setting `ref`: no Python frame to run
    "Term": Term,
    "INLINE": INLINE,
    "CALL": CALL,
    "SEQ": SEQ,
    "DISJ": DISJ,
    "ITE": ITE,
    "IFTHEN": IFTHEN,
    "NOT": NOT,
    "univ_list": univ_list,
    "univ_compose": univ_compose,
    "mkt": make_term,  # `mkt((name, args))`: a Term without tuple.__new__'s checks
    "unify": unify,
    "identical": identical,
    "ev": evaluate,
    "ap2": apply_binary,
    "arg_check": arg_check,
    "functor_make": functor_make,
    "fresh_vars": fresh_vars,
}
# Generated factories are pure functions of their source text (constants are parameters),
# so one bounded memo serves every knowledge base without sharing any resolved state.
FACTORY_CACHE_SIZE = 4096
_FACTORIES: LRUCache[str, Factory] = LRUCache(FACTORY_CACHE_SIZE)
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


def make_factory(source: str) -> Factory:
    """Execute generated source defining `make(...)`, once per distinct source text."""
    factory = _FACTORIES.get(source)
    if factory is None:
        # exec binds `make` here; what it is shows only in the source, so the values are Any.
        namespace: dict[str, Any] = dict(_NAMESPACE)
        exec(compiled(source), namespace)  # noqa: S102
        factory = namespace["make"]
        _FACTORIES.put(source, factory)
    return factory


def function_factory(source: str, name: str) -> Factory:
    """The factory of function `name` defined by generated `source`, its constants read
    as globals `k0, k1, ...` (see function_factory.py); once per distinct source text."""
    factory = _FACTORIES.get(source)
    if factory is None:
        factory = FunctionFactory(compiled(source), name, _NAMESPACE)
        _FACTORIES.put(source, factory)
    return factory


_GROUND_NODES = 8  # a ground compound in a head up to this size is read inline


def _nodes(t: Value, budget: int) -> int:
    """`budget` less the compounds and constants in ground term `t`; <= 0 when it runs out
    or `t` holds anything but atoms, integers and compounds (a float, a string...)."""
    if type(t) is Term:
        budget -= 1
        for a in t[1]:
            if budget <= 0:
                return 0
            budget = _nodes(a, budget)
        return budget
    return budget - 1 if type(t) is str or type(t) is int else 0


def deref_line(x: str) -> str:
    """The statement dereferencing local `x` in place."""
    return f"while type({x}) is Var and {x}.ref is not None: {x} = {x}.ref"


def slots_in(t: Value, out: list[int]) -> list[int]:
    """Collect the slot numbers in a template, in order of first appearance."""
    if type(t) is Slot:
        if t.i not in out:
            out.append(t.i)
    elif type(t) is Tmpl:
        for a in t.args:
            slots_in(a, out)
    return out


def term_parts(t: Value) -> tuple[str, tuple[Value, ...]] | None:
    """Name and arguments of a compound term or template; None for anything else."""
    if type(t) is Tmpl:
        return t.name, t.args
    if type(t) is Term:
        return t[0], t[1]
    return None


def inlinable(g: Value) -> bool:
    """True for a goal that runs inline once its slots hold values (tests, is/2, =/2)."""
    parts = term_parts(g)
    if parts is None:
        return g == "true"
    name, args = parts
    if len(args) == 1:
        return name in _TYPE_TESTS
    if name == "=.." and len(args) == 2:
        return type(args[0]) is Slot
    if (name, len(args)) in TERM_GOALS:
        return True
    return len(args) == 2 and (name in _COMPARE_OPS or name in _INLINE_BINARY)


_INLINE_BINARY = frozenset(["is", "=", "==", "\\=="])


def inline_function(
    goals: list[Value], slots: list[int], unbound: set[int] | frozenset[int] = frozenset()
) -> Callable[..., bool] | None:
    """Compile inline goals to `fn(trail, values of slots)`: true when all succeed.

    `unbound`: slots holding a new variable that nothing else can have bound or shared
    when the run starts; `X is E` with such an X binds it without unifying, until a goal
    names it. None when one of the goals cannot run inline after all.
    """
    writer = GoalWriter()
    writer.known = set(slots)
    writer.unbound = set(unbound)
    for g in goals:
        if not writer.inline_goal(g):
            return None
        writer.unbound.difference_update(slots_in(g, []))
    params = ", ".join(f"k{i}" for i in range(len(writer.consts)))
    head = [f"def make({params}):", "  def fn(trail, values):"]
    if slots:  # one tuple, unpacked here: a call with *values costs several times more
        head.append(f"    {''.join(f'v{i}, ' for i in slots)}= values")
    source = "\n".join([*head, *writer.lines, "    return True", "  return fn", ""])
    return make_factory(source)(*writer.consts)


class GoalWriter:
    """Emits Python source for inline goals, tracking which slots hold values."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.consts: list[Value] = []
        self.known: set[int] = set()
        self.dereffed: set[int] = set()
        self.unbound: set[int] = set()  # slots known to hold a new, unshared variable
        self.temps = 0
        self.base = 0
        self.fail = "return False"  # the statement a failing head or inline goal runs

    def emit(self, line: str, depth: int) -> None:
        self.lines.append("  " * (depth + self.base + 1) + line)

    def const(self, value: Value) -> str:
        self.consts.append(value)
        return f"k{len(self.consts) - 1}"

    def temp(self) -> str:
        self.temps += 1
        return f"t{self.temps}"

    def fresh(self, templates: list[Value], depth: int) -> None:
        """Give each slot not yet holding a value a new unbound variable."""
        found: list[int] = []
        for t in templates:
            slots_in(t, found)
        for i in found:
            if i not in self.known:
                self.emit(f"v{i} = newv(); v{i}.ref = None", depth)
                self.known.add(i)

    def build(self, t: Value) -> str:
        """Python expression building template `t` (all its slots must be known)."""
        if type(t) is Slot:
            return f"v{t.i}"
        if type(t) is Tmpl:
            args = "".join(f"{self.build(a)}, " for a in t.args)
            return f"mkt(({self.const(t.name)}, ({args})))"
        return self.const(t)

    def cut(self) -> None:
        """Emit a cut at the neck: drop the choicepoints made since the clause began."""
        self.emit("del cps[cb:]", 1)

    def unify_arg(self, p: Value, x: str, depth: int) -> None:
        """Emit code unifying template `p` with the (un-dereferenced) value in local `x`."""
        if type(p) is Slot:
            if p.i in self.known:
                self.unify_locals(f"v{p.i}", x, depth)
                self.dereffed.discard(p.i)
            else:
                self.emit(f"v{p.i} = {x}", depth)
                self.known.add(p.i)
            return
        if type(p) is Term and _nodes(p, _GROUND_NODES) > 0:
            self.ground_term(p, x, depth)
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
        self.emit(f"elif type({x}) is Term and {x}[0] == {name}:", depth)
        self.read_args(p.args, f"{x}[1]", depth + 1, checked=False)
        self.emit(f"else: {self.fail}", depth)

    def ground_term(self, p: Term, x: str, depth: int) -> None:
        """Emit unifying a small ground compound with local `x`: bind it, or read it
        argument by argument (as a template is read) instead of calling `unify`."""
        self.emit(deref_line(x), depth)
        self.emit(f"if type({x}) is Var: {x}.ref = {self.const(p)}; trail.append({x})", depth)
        name = self.const(p[0])
        self.emit(f"elif type({x}) is Term and {x}[0] == {name}:", depth)
        self.read_args(p[1], f"{x}[1]", depth + 1, checked=False)
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

    def read_args(
        self, pargs: tuple[Value, ...], src: str, depth: int, checked: bool = True
    ) -> None:
        """Read mode: unpack the call's subterms, then unify each with its template.

        Unless `checked` (the arity is known to match), the unpacking itself checks it: a
        tuple of another length raises ValueError, which fails. That costs nothing when it
        matches, where `len(x[1]) == n` took a subscript, a call and a comparison.
        """
        names: list[str] = []
        later: list[tuple[Value, str]] = []
        for a in pargs:
            if type(a) is Slot and a.i not in self.known:
                names.append(f"v{a.i}")
                self.known.add(a.i)
            else:
                t = self.temp()
                names.append(t)
                later.append((a, t))
        unpack = f"{''.join(n + ', ' for n in names)}= {src}"
        if not names:  # no arguments (never read in Prolog text): only the length
            if not checked:
                self.emit(f"if {src}: {self.fail}", depth)
        elif checked:
            self.emit(unpack, depth)
        else:
            self.emit(f"try: {unpack}", depth)
            self.emit(f"except ValueError: {self.fail}", depth)
        for a, t in later:
            self.unify_arg(a, t, depth)

    def inline_goal(self, g: Value) -> bool:
        """Emit a leading deterministic built-in inline; False when `g` is not one."""
        if g == "!":
            self.cut()
            return True
        if g == "true":
            return True
        parts = term_parts(g)
        if parts is not None and len(parts[1]) == 1 and parts[0] in _TYPE_TESTS:
            return self.type_test(parts[0], parts[1][0])
        if parts is not None and (parts[0], len(parts[1])) in TERM_GOALS:
            return emit_term_goal(self, parts[0], parts[1])
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
            if type(left) is Slot and left.i in self.unbound and left.i not in slots_in(right, []):
                v = f"v{left.i}"  # a number: binding the new variable is the unification
                self.emit(f"{v}.ref = {value}; trail.append({v})", 1)
                self.dereffed.discard(left.i)
                return True
            self.assign_or_unify(left, value)
            return True
        if name == "=..":
            return self.univ(left, right)
        if name == "=":
            if type(right) is Slot and right.i not in self.known:
                left, right = right, left
            if type(left) is Slot and left.i not in self.known:
                if left.i in slots_in(right, []):
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

    def univ(self, term: Value, items: Value) -> bool:
        """Emit `Term =.. Items` for a slot `Term`: taken apart, or built when unbound."""
        if type(term) is not Slot or term.i in slots_in(items, []):
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
        self.dereffed = dereffed - {term.i, *slots_in(items, [])}
        return True

    def test(self, g: Value) -> str | None:
        """A Python condition for test goal `g` (type tests, comparisons, `\\+`, `,`)."""
        if g in ("true", "fail", "false"):
            return "True" if g == "true" else "False"
        parts = term_parts(g)
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
            if any(i not in self.known for i in slots_in(g, [])):
                return None
            same = f"identical({self.build(args[0])}, {self.build(args[1])})"
            return same if name == "==" else f"not {same}"
        return None

    def deref_slot(self, i: int) -> None:
        """Dereference slot `i` in place, once."""
        if i not in self.dereffed:
            self.emit(deref_line(f"v{i}"), 1)
            self.dereffed.add(i)

    def type_test(self, name: str, arg: Value) -> bool:
        """Emit a type test (`number(X)`, `var(X)`, ...) of a slot holding a value."""
        if type(arg) is not Slot or arg.i not in self.known:
            return False
        self.deref_slot(arg.i)
        self.emit(f"if not ({_TYPE_TESTS[name].format(f'v{arg.i}')}): {self.fail}", 1)
        return True

    def assign_or_unify(self, target: Value, value: str) -> None:
        """Bind a fresh slot to `value` directly, or unify `target` with it."""
        if type(target) is Slot and target.i not in self.known:
            self.emit(f"v{target.i} = {value}", 1)
            self.known.add(target.i)
            self.dereffed.add(target.i)  # a number
            return
        result = self.temp()
        self.emit(f"{result} = {value}", 1)
        self.unify_arg(target, result, 1)

    def expr(self, t: Value) -> str | None:
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
        parts = term_parts(t)
        if parts is not None:
            name, args = parts
            if len(args) == 2 and name in BINARY_FUNCTIONS:
                a, b = self.expr(args[0]), self.expr(args[1])
                if a is None or b is None:
                    return None
                if name in _ARITH_OPS:
                    return f"({a} {_ARITH_OPS[name]} {b})"
                if name in INT_FAST:
                    return int_fast(name, a, b, self.temp(), self.temp(), self.const(name))
                return f"ap2({self.const(name)}, {a}, {b})"
            if any(i not in self.known for i in slots_in(t, [])):
                return None
        return f"ev({self.build(t)})"
