"""A knowledge base: predicates loaded in named fact groups, Python predicates, queries.

Fact groups follow CRAM: loading a group again replaces its clauses, and a group may only
add clauses to a predicate owned by another group when one of the two declares it
extendable. Queries are lazy: each answer is computed when the iterator is advanced.
"""

from __future__ import annotations

import difflib
import threading
from collections.abc import Callable, Iterable, Iterator

from robocram.logic.arith import MAX_INTEGER_BITS
from robocram.logic.builtin_flags import default_flags
from robocram.logic.bulk import paused_gc
from robocram.logic.clause import Clause
from robocram.logic.convert import SelfContainingValue, to_prolog, to_python
from robocram.logic.errors import (
    PrologError,
    PrologPermissionError,
    PrologResourceError,
)
from robocram.logic.fact_groups import LIBRARY_OWNER, GroupEdit, Groups, refuse_system
from robocram.logic.kept_reads import keep_terms, kept_terms
from robocram.logic.keys import pred_key
from robocram.logic.limits import Budget, QueryStopped
from robocram.logic.loader import compile_clause, parse_indicator
from robocram.logic.lru import LRUCache
from robocram.logic.machine import Machine
from robocram.logic.operators import OperatorTable
from robocram.logic.predicate import USER, Key, Pred
from robocram.logic.reader import read_query, read_terms
from robocram.logic.shared_reads import STANDARD_SYNTAX
from robocram.logic.system import PRIVATE_PREFIX, library_predicates, system_predicates
from robocram.logic.template import Slot, build, compile_term
from robocram.logic.terms import Term, Var, deref
from robocram.logic.usage_errors import LogicUsageError
from robocram.logic.value import Value

__all__ = ["KnowledgeBase"]

PyPredicate = Callable[..., Iterator[object]]
QUERY_CACHE_SIZE = 1024
CONSULT_CACHE_SIZE = 64  # texts consulted again and again (an environment's set-up)
Compiled = list[tuple[Key, Clause]]


class KnowledgeBase:
    """Predicates, fact groups and Python functions, queried with Prolog text.

    >>> kb = KnowledgeBase()
    >>> kb.consult("parent(tom, bob). parent(bob, ann). anc(X, Y) :- parent(X, Y).")
    >>> [a["Y"] for a in kb.query("anc(tom, Y)")]
    ['bob']
    """

    def __init__(self) -> None:
        # One dict for the machine's lookup: the shared, frozen system predicates plus this
        # KB's own library and user predicates.
        self._preds: dict[Key, Pred] = dict(system_predicates())
        self._preds.update(library_predicates())
        self._ops = OperatorTable()
        self._functions: dict[str, Callable[..., object]] = {}
        self._flags: dict[str, Value] = default_flags(MAX_INTEGER_BITS)
        self._groups: Groups = {}
        self._lock = threading.RLock()
        self._queries: LRUCache[tuple[str, str], tuple[Value, dict[str, int], int]] = LRUCache(
            QUERY_CACHE_SIZE
        )
        self._generation = 0  # see `generation`
        self._syntax = 0  # changes with the operators and flags, which change how text reads
        self._consulted: LRUCache[tuple[str, str, int], Compiled] = LRUCache(CONSULT_CACHE_SIZE)

    @property
    def generation(self) -> int:
        """A number that changes whenever the clauses, predicates, operators or flags do.

        Every way of changing them (consult, fact groups, assert, retract, retractall,
        abolish, dynamic, op, set_prolog_flag, Python predicates and functions, from Python
        or from inside a query) calls :meth:`mark_changed`. Loading a group again with the
        same clauses does not count. A caller may keep the answers of a query over static
        rules keyed on ``(generation, inputs)``, as long as no Python predicate the query
        runs reads anything else (the world) -- or that is part of its key as well.
        """
        return self._generation

    def mark_changed(self, syntax: bool = False) -> None:
        """Note a change of clauses or predicates (``syntax``: of operators or flags)."""
        with self._lock:
            self._generation += 1
            if syntax:
                self._syntax += 1

    def consult(
        self, text: str, group: str | None = None, extendable: Iterable[Value] = ()
    ) -> None:
        """Load Prolog text as fact group `group` (replacing it); None appends to 'user'.

        All or nothing: when a clause is refused or a directive fails or raises, the
        knowledge base is left as it was, and a concurrent query sees the old group or the
        new one, never a mix.
        """
        name = group or "user"
        directives: list[Value] = []
        dynamic: list[Key] = []
        compiled = self._consulted_before(name, text) if group is not None else None
        if compiled is None:
            syntax = self._syntax
            compiled = self._read_clauses(text, name, directives, dynamic)
            if group is not None and not directives and not dynamic and syntax == self._syntax:
                self._consulted.put((name, text, syntax), compiled)
        with self._lock:
            before = (self._preds, self._groups)
            self._commit(name, group is not None, compiled, extendable, dynamic)
            try:
                for goal in directives:
                    if not self.holds_term(goal):
                        raise PrologError(f"directive failed: {goal!r} (in fact group {name!r})")
            except BaseException:
                self._preds, self._groups = before
                self.mark_changed()
                raise

    def _read_clauses(
        self, text: str, name: str, directives: list[Value], dynamic: list[Key]
    ) -> Compiled:
        """Read and compile the clauses of ``text``; collect its directives and dynamics.

        In the standard syntax (``_syntax`` 0) a text without directives is read once per
        process (:mod:`~robocram.logic.shared_reads`) and once per machine
        (:mod:`~robocram.logic.kept_reads`)."""
        standard = self._syntax == 0
        kept = STANDARD_SYNTAX.clauses(text, name) if standard else None
        if kept is not None:
            return kept
        with paused_gc():
            stored = kept_terms(text) if standard else None
            if stored is not None:
                compiled = [compile_clause(t, name) for t in stored]
                STANDARD_SYNTAX.keep_clauses(text, compiled)
                return compiled
            terms: list[Value] = []
            plain = True
            for term, _ in read_terms(text, self._ops, self._flags):
                if type(term) is Term and term[0] == ":-" and len(term[1]) == 1:
                    plain = False
                    if not self._declaration(deref(term[1][0]), dynamic):
                        directives.append(term[1][0])
                else:
                    terms.append(term)
            compiled = [compile_clause(t, name) for t in terms]
            if standard and plain:
                STANDARD_SYNTAX.keep_clauses(text, compiled)
                keep_terms(text, terms)
            return compiled

    def _consulted_before(self, name: str, text: str) -> Compiled | None:
        """The clauses ``text`` compiled to when group ``name`` last loaded it, if reusable.

        Reused clauses keep their generated code, and a group loaded again unchanged
        keeps its predicates' compiled procedures (see ``_commit``). Only texts of a named
        group (which replaces its old clauses) without directives are kept, and their
        clauses only while no predicate of theirs is dynamic: a static clause is never
        retracted, so it is still as compiled.
        """
        compiled = self._consulted.get((name, text, self._syntax))
        if compiled is None:
            return None
        preds = self._preds
        for key, clause in compiled:
            pred = preds.get(key)
            if clause.erased or (pred is not None and pred.dynamic):
                return None
        return compiled

    def add_fact_group(
        self, group: str | None, clauses: Iterable[Value], extendable: Iterable[Value] = ()
    ) -> None:
        """Define fact group `group` from clause texts or terms (see `consult`)."""
        name = group or "user"
        compiled: list[tuple[Key, Clause]] = []
        for clause in clauses:
            if isinstance(clause, str):
                compiled.extend(
                    compile_clause(t, name) for t, _ in read_terms(clause, self._ops, self._flags)
                )
            else:
                compiled.append(compile_clause(to_prolog(clause), name))
        with self._lock:
            self._commit(name, group is not None, compiled, extendable, ())

    def _commit(
        self,
        name: str,
        replace: bool,
        compiled: list[tuple[Key, Clause]],
        extendable: Iterable[Value],
        dynamic: Iterable[Key],
    ) -> None:
        """Stage the group on copies and install them in one step (hold the lock)."""
        shared = {parse_indicator(to_prolog(e)) for e in extendable}
        edit = GroupEdit(self._preds, self._groups)
        edit.load(name, replace, compiled, shared, dynamic)
        if edit.keep_unchanged() and edit.groups == self._groups:
            return  # the same clauses again: keep the predicates and their compiled code
        self._preds, self._groups = edit.preds, edit.groups
        self.mark_changed()

    def _declaration(self, goal: Value, dynamic: list[Key]) -> bool:
        """Handle dynamic/discontiguous/op directives; False for goals to run."""
        if (
            type(goal) is not Term
            or len(goal[1]) != 1
            or goal[0] not in ("dynamic", "discontiguous")
        ):
            if type(goal) is Term and (goal[0], len(goal[1])) in _READER_DIRECTIVES:
                self.holds_term(goal)
                return True
            return False
        if goal[0] == "dynamic":
            dynamic.extend(parse_indicator(spec) for spec in _comma_items(goal[1][0]))
        return True

    def declare_dynamic(self, key: Key) -> None:
        """Make name/arity a dynamic predicate (defined, modifiable by assert/retract)."""
        with self._lock:
            self._user_pred(key).dynamic = True
            self.mark_changed()

    def _user_pred(self, key: Key) -> Pred:
        """The user predicate `key` in place (created, or taken over from the library)."""
        pred = self._preds.get(key)
        if pred is None or pred.owner == LIBRARY_OWNER:
            # stored under the shared key, which clause code's calls hold (keys.py)
            pred = self._preds[pred_key(key[0], key[1])] = Pred(key[0], key[1])
        elif pred.system or pred.kind != USER:
            raise refuse_system(pred)
        return pred

    def assert_clause(self, clause: Value, front: bool = False) -> None:
        """Add a clause to a dynamic (or new) predicate, as assertz/asserta do."""
        self.assert_term(to_prolog(clause), front)

    def assert_term(self, clause: Value, front: bool = False) -> None:
        """`assert_clause` for a clause already in engine form (compiling copies it)."""
        key, compiled = compile_clause(clause, None, shared_key=False)
        with self._lock:
            pred = self._preds.get(key)
            if (
                pred is not None
                and not pred.dynamic
                and pred.owner != LIBRARY_OWNER
                and (pred.clauses or pred.system or pred.kind != USER)
            ):
                raise PrologPermissionError(
                    "modify",
                    "static_procedure",
                    Term("/", key),
                    f"{pred.indicator} is static (loaded from fact group '{pred.owner}');"
                    " declare it"
                    f" with ':- dynamic {pred.indicator}.' to assert into it",
                )
            pred = self._user_pred(key)
            pred.dynamic = True
            if front:
                pred.add_first(compiled)
            else:
                pred.add_last(compiled)
            self.mark_changed()

    def assertz(self, clause: Value) -> None:
        """Append a clause (Prolog text or term) to a dynamic predicate."""
        for term in self._clause_terms(clause):
            self.assert_clause(term)

    def asserta(self, clause: Value) -> None:
        """Prepend a clause (Prolog text or term) to a dynamic predicate."""
        for term in self._clause_terms(clause):
            self.assert_clause(term, front=True)

    def retract(self, clause: Value) -> bool:
        """Remove the first clause unifying with `clause`; return whether one was removed."""
        term = (
            read_query(clause, self._ops, self._flags)[0]
            if isinstance(clause, str)
            else to_prolog(clause)
        )
        return self.holds_term(Term("retract", (term,)))

    def _clause_terms(self, clause: Value) -> list[Value]:
        if isinstance(clause, str):
            return [
                t
                for t, _ in read_terms(
                    clause if clause.rstrip().endswith(".") else clause + ".", self._ops
                )
            ]
        return [clause]

    def predicate(self, name: str, arity: int) -> Callable[[PyPredicate], PyPredicate]:
        """Decorator registering a Python generator as predicate name/arity."""

        def decorate(fn: PyPredicate) -> PyPredicate:
            self.add_predicate(name, arity, fn)
            return fn

        return decorate

    def add_predicate(self, name: str, arity: int, fn: PyPredicate) -> None:
        """Register `fn(*args)` yielding tuples of `arity` values (or None) as name/arity."""
        if not callable(fn):
            raise LogicUsageError(f"add_predicate({name!r}, {arity}): {fn!r} is not callable")
        with self._lock:
            self._user_pred((name, arity)).pyfn = fn
            self.mark_changed()

    def register_function(self, name: str, fn: Callable[..., object]) -> None:
        """Make `fn` callable by name from py_fun/N and py_pred/N."""
        if not callable(fn):
            raise LogicUsageError(f"register_function({name!r}): {fn!r} is not callable")
        self._functions[name] = fn
        self.mark_changed()

    def predicates(self, include_builtins: bool = False) -> list[str]:
        """Sorted `name/arity` of the defined predicates (user ones unless asked)."""
        return sorted(
            p.indicator
            for p in list(self._preds.values())
            if not p.name.startswith(PRIVATE_PREFIX)
            and (include_builtins or not p.system and p.kind == USER and p.owner != LIBRARY_OWNER)
        )

    def defines(self, indicator: str) -> bool:
        """Whether ``name/arity`` is one of :meth:`predicates` (without listing them all)."""
        name, _, arity = indicator.rpartition("/")
        pred = self._preds.get((name, int(arity))) if arity.isdigit() else None
        return (
            pred is not None
            and not pred.name.startswith(PRIVATE_PREFIX)
            and not pred.system
            and pred.kind == USER
            and pred.owner != LIBRARY_OWNER
        )

    def known(self, name: str, arity: int) -> bool:
        """Whether a call of ``name/arity`` finds a predicate (of any kind) rather than
        raising an unknown-predicate error, without building that error's suggestions."""
        return (name, arity) in self._preds

    def similar_predicates(self, name: str, arity: int) -> list[str]:
        """Defined predicates whose name or arity is close to name/arity."""
        preds = list(self._preds.values())
        same = [p.indicator for p in preds if p.name == name and p.arity != arity]
        names = {p.name for p in preds}
        close = difflib.get_close_matches(name, names, n=3, cutoff=0.75)
        near = [p.indicator for p in preds if p.name in close and p.name != name]
        return (
            sorted(set(same))[:3]
            + sorted(set(near), key=lambda s: s.split("/")[0] not in close[:1])[:3]
        )

    def query(
        self,
        text: str,
        *,
        max_inferences: int | None = None,
        time_limit: float | None = None,
        **bindings: Value,
    ) -> Iterator[dict[str, Value]]:
        """Lazily yield one dict per answer, mapping the query's free variable names to values.

        `max_inferences` and `time_limit` [s, counted from the first answer asked for] stop
        a runaway query with InferenceLimitExceeded / TimeLimitExceeded (catchable in the
        query as resource_error(inferences) / resource_error(time)).
        """
        limits = (max_inferences, time_limit)
        if max_inferences is not None or time_limit is not None:
            Budget(*limits)  # check the limits now, not at the first answer
        template, names, nslots = self._compile_query(text)
        regs: list[Value] = [None] * nslots
        for name, value in bindings.items():
            if name not in names:
                raise PrologError(
                    f"binding {name}= names no variable of query {text!r}; its variables are"
                    f" {', '.join(sorted(names)) or 'none'}"
                )
            try:
                regs[names[name]] = to_prolog(value)
            except SelfContainingValue as err:
                raise PrologResourceError("term_depth", f"binding {name}= is {err}") from err
        goal = build(template, regs)
        shown = [(n, i) for n, i in names.items() if n not in bindings and not n.startswith("_")]
        return self._answers(goal, regs, shown, limits)

    def _answers(
        self,
        goal: Value,
        regs: list[Value],
        shown: list[tuple[str, int]],
        limits: tuple[int | None, float | None],
    ) -> Iterator[dict[str, Value]]:
        solutions = Machine(self, Budget(*limits)).solve(goal)
        while True:
            try:
                next(solutions)
            except StopIteration:
                return
            except QueryStopped as stop:  # the stop hook (a task's checkpoint) said stop
                raise stop.original from None
            try:
                answer = {name: to_python(regs[i]) for name, i in shown}
            except RecursionError as err:  # a cyclic or very deeply nested answer
                raise PrologResourceError(
                    "term_depth",
                    "an answer is cyclic or nested too deeply to convert to Python values;"
                    " return a smaller term or test it with acyclic_term/1",
                ) from err
            yield answer

    def _compile_query(self, text: str) -> tuple[Value, dict[str, int], int]:
        key = (self._flags["double_quotes"], text)  # the flag changes what "..." reads as
        cached = self._queries.get(key)
        if cached is None:
            standard = self._syntax == 0  # the standard syntax: read once per process
            cached = STANDARD_SYNTAX.query(text) if standard else None
            if cached is None:
                term, varmap = read_query(text, self._ops, self._flags)
                slots: dict[Var, Slot] = {}
                for var in varmap.values():
                    slots[var] = Slot(len(slots))
                template = compile_term(term, slots)
                cached = (template, {name: slots[v].i for name, v in varmap.items()}, len(slots))
                if standard:
                    STANDARD_SYNTAX.keep_query(text, cached)
            self._queries.put(key, cached)
        return cached

    def holds(self, text: str, **bindings: Value) -> bool:
        """True when the query has at least one answer."""
        return next(self.query(text, **bindings), None) is not None

    def first(self, text: str, **bindings: Value) -> dict[str, Value] | None:
        """The first answer of the query, or None when it has none."""
        return next(self.query(text, **bindings), None)

    def holds_term(self, goal: Value) -> bool:
        """Run an engine term as a goal; True when it has a solution."""
        try:
            return next(Machine(self).solve(to_prolog(goal)), False) is None
        except QueryStopped as stop:
            raise stop.original from None

    def __repr__(self) -> str:
        return f"KnowledgeBase({len(self.predicates())} predicates, groups={sorted(self._groups)})"


# Directives that change how the rest of the text reads: run as soon as they are read.
_READER_DIRECTIVES = frozenset([("op", 3), ("set_prolog_flag", 2)])


def _comma_items(t: Value) -> list[Value]:
    """Items of `a, b, c` or of a list `[a, b, c]` (as in `:- dynamic`)."""
    t = deref(t)
    items = []
    sep = "." if type(t) is Term and t[0] == "." else ","
    while type(t) is Term and t[0] == sep and len(t[1]) == 2:
        items.append(t[1][0])
        t = deref(t[1][1])
    if sep == ",":
        items.append(t)
    return items
