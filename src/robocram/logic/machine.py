"""The resolution machine: a goal continuation list, a choicepoint stack and a trail.

No Python recursion per call: a continuation is a linked tuple (goal, cut_barrier, next),
and the last goal of a clause body continues with the parent's continuation, so deep
deterministic recursion runs in constant stack space. Cut removes the choicepoints above
the barrier recorded when the clause was entered.
"""

from __future__ import annotations

from collections.abc import Iterator

from robocram.logic import gc_pacing
from robocram.logic.builtin_flags import warn_unknown
from robocram.logic.choicepoints import (
    ALT,
    BARRIER,
    CATCH,
    CLAUSES,
    GEN,
    PROC,
    REACT,
    ChoicePoint,
    Cont,
)
from robocram.logic.clause import Clause
from robocram.logic.codegen import ClauseFn
from robocram.logic.control import FAIL, run_control
from robocram.logic.engine import Database
from robocram.logic.errors import (
    PrologError,
    PrologHostError,
    PrologInstantiationError,
    PrologResourceError,
    PrologTypeError,
    UnknownPredicateError,
)
from robocram.logic.fact_groups import LIBRARY_OWNER
from robocram.logic.inline_goal import CALL, DISJ, IFTHEN, INLINE, ITE, MARKS, NOT, SEQ
from robocram.logic.limits import PROC_LOOPS, Budget
from robocram.logic.occurs import unify_checked
from robocram.logic.predicate import DET, NONDET, USER, WARM_CALLS, Pred
from robocram.logic.procedure import Procedure
from robocram.logic.python_predicates import python_solutions
from robocram.logic.terms import Term, Var, make_term
from robocram.logic.unify import copy_resolved, undo, unify
from robocram.logic.value import Value

__all__ = ["Machine"]

TICK_CHUNK = 256  # the machine's inference count stays a cached small int (see _run)


class Machine:
    """Per-query solver state: the trail shared by nested solves, and the knowledge base."""

    def __init__(self, kb: Database, budget: Budget | None = None) -> None:
        self.kb = kb
        self.preds = kb._preds
        self.trail: list[Var] = []
        self.budget = budget if budget is not None else Budget(None, None)
        self.occurs_check: str = kb._flags["occurs_check"]

    def unify(self, a: Value, b: Value) -> bool:
        """Unify two terms, trailing the bindings (for built-ins)."""
        if self.occurs_check != "false":
            return unify_checked(a, b, self.trail, self.occurs_check == "error")
        return unify(a, b, self.trail)

    def clause_runner(self, cl: Clause) -> ClauseFn:
        """The function to run clause `cl` with: compiled, or checked for the occurs check."""
        if self.occurs_check == "false":
            return cl.run if cl.run is not None else cl.prepare()
        return cl.interpret_checked if self.occurs_check == "true" else cl.interpret_error

    def undo_to(self, mark: int) -> None:
        """Undo bindings made since the trail had length `mark`."""
        undo(self.trail, mark)

    def unknown(self, name: str, arity: int) -> UnknownPredicateError:
        """Build the error for a call to an undefined predicate."""
        return UnknownPredicateError(name, arity, self.kb.similar_predicates(name, arity))

    def _undefined(self, name: str, arity: int) -> None:
        """Raise for a call to an undefined predicate, unless the `unknown` flag says fail."""
        mode = self.kb._flags["unknown"]
        if mode == "error":
            raise self.unknown(name, arity)
        if mode == "warning":
            warn_unknown(name, arity)

    def solve(
        self, goal: Value, sub: bool = False, cps: list[ChoicePoint] | None = None
    ) -> Iterator[None]:
        """Yield once per solution of `goal`, with its bindings in place while suspended.

        `cps`, an empty list, lets the caller see the choicepoints left after a solution.
        """
        trail = self.trail
        if cps is None:
            cps = []
        if sub:
            cps.append([BARRIER, len(trail)])
        cont: Cont = (goal, len(cps), None)
        fail = False
        while True:
            try:
                yield from self._run(cps, cont, fail)
                return
            except PrologError as err:
                cont = self._handle(err, cps, sub)
                fail = False

    def _handle(self, err: PrologError, cps: list[ChoicePoint], sub: bool) -> Cont:
        """Find the innermost active catch/3 whose catcher unifies with the ball."""
        ball = copy_resolved(err.ball)
        err.ball = ball
        trail = self.trail
        while cps:
            cp = cps.pop()
            if cp[0] == BARRIER:
                break
            if cp[0] == CATCH and cp[6]:
                undo(trail, cp[1])
                if unify(cp[2], ball, trail):
                    return (cp[3], len(cps), cp[4])
                undo(trail, cp[1])
        if isinstance(err, PrologHostError) and not sub:
            raise err.original  # nothing caught it: the caller sees its own exception
        raise err

    def _run(self, cps: list[ChoicePoint], cont: Cont, fail: bool) -> Iterator[None]:
        # The hot loop: one iteration per goal. It is written flat on purpose (locals cached,
        # `type(x) is` tests, first-argument indexing inlined) because every helper call
        # here costs a measurable share of an inference; the cold paths are methods.
        trail = self.trail
        preds = self.preds
        backtrack = self._backtrack
        if fail:
            cont = backtrack(cps)
        goal: Value = None
        budget = self.budget
        spend = budget.spend
        # Inferences are counted down in chunks of at most TICK_CHUNK: an int up to 256
        # is CPython's cached object, so the count costs no allocation per goal. The
        # budget is charged `every` inferences when `due` of them have run, as before.
        every = due = budget.interval()
        left = chunk = min(due, TICK_CHUNK)
        plain = self.occurs_check == "false"  # procedures skip the occurs check
        pacer = gc_pacing.current_pacer()  # paces only inside `with fast_queries():`
        pacer.enter()
        running = True
        try:
            while True:
                while cont is None:
                    pacer.leave()
                    running = False
                    yield None
                    pacer.enter()
                    running = True
                    left -= 1  # a redo: the loop of `between(1, N, X)` under findall/3
                    if not left:
                        due -= chunk
                        if not due:
                            every = due = spend(every)
                        left = chunk = min(due, TICK_CHUNK)
                    cont = backtrack(cps)
                if cont is False:
                    return
                left -= 1
                if not left:
                    due -= chunk
                    if not due:
                        every = due = spend(every)
                    left = chunk = min(due, TICK_CHUNK)
                goal, cutb, nxt = cont
                tg = type(goal)
                if tg is tuple:  # built by clause code (see inline_goal.py)
                    name, args, mark = goal
                    if mark is not CALL:
                        if mark is INLINE:
                            cont = nxt if name(trail, args) else backtrack(cps)
                        elif mark is DISJ:
                            cps.append([ALT, len(trail), (args, cutb, nxt)])
                            cont = (name, cutb, nxt)
                        elif mark is ITE:  # a then-branch None is `true`
                            b = len(cps)
                            cps.append([ALT, len(trail), (args[1], cutb, nxt)])
                            then = args[0]
                            if then is not None:
                                nxt = (then, cutb, nxt)
                            cont = (name, b + 1, ("!", b, nxt))  # the cut to b ends it
                        elif mark is SEQ:
                            cont = (name, cutb, (args, cutb, nxt))
                        elif mark is IFTHEN:
                            b = len(cps)
                            if args is not None:
                                nxt = (args, cutb, nxt)
                            cont = (name, b, ("!", b, nxt))
                        elif mark is NOT:
                            b = len(cps)
                            cps.append([ALT, len(trail), nxt])
                            cont = (name, b + 1, ("!", b, FAIL))
                        else:
                            cont = self._call_other(goal, len(cps), nxt)
                        continue
                    # A call's first item is its (name, arity) key; `name` stays that key
                    # until a path below needs the name itself.
                    try:
                        q = preds[name]
                    except KeyError:
                        p = None
                    else:  # the commonest goal: a compiled procedure, called at once
                        proc = q.proc
                        if proc is not None and plain:
                            cont = proc(args, trail, nxt, cps, 0)
                            if type(cont) is not tuple:  # one test for the common return
                                if cont is False:
                                    cont = backtrack(cps)
                                elif cont is not None:  # handed back (see _again)
                                    cont = self._again(proc, cont, nxt, cps)
                                    if cont is False:
                                        cont = backtrack(cps)
                            continue
                        p = q
                elif tg is Term:
                    name = goal[0]
                    args = goal[1]
                    p = preds.get((name, len(args)))
                elif tg is str:
                    if goal == "!":  # the commonest atom goal: no lookup
                        del cps[cutb:]
                        cont = nxt
                        continue
                    name = goal
                    args = ()
                    p = preds.get((name, 0))
                else:
                    cont = self._call_other(goal, len(cps), nxt)
                    continue
                if p is None:
                    self._undefined(name[0] if type(name) is tuple else name, len(args))
                    cont = backtrack(cps)
                    continue
                proc = p.proc  # only user predicates have one
                if proc is not None and plain:
                    cont = proc(args, trail, nxt, cps, 0)
                    if cont is False:
                        cont = backtrack(cps)
                    elif type(cont) is list:
                        cont = self._again(proc, cont, nxt, cps)
                        if cont is False:
                            cont = backtrack(cps)
                    continue
                k = p.kind
                if k == USER:
                    if p.pyfn is not None:
                        if not cps and trail:
                            del trail[:]
                        self._push_python(p, args, nxt, cps)
                        cont = backtrack(cps)
                        continue
                    if p.warm < WARM_CALLS:
                        # a library or system predicate's code may serve other bases
                        own = not p.system and p.owner != LIBRARY_OWNER
                        p.warm_up(self.kb if own else None)
                    cont = self._call_clauses(p, args, nxt, cps)
                    if cont is False:
                        cont = backtrack(cps)
                elif k == DET:
                    cont = nxt if p.fn(self, args) else backtrack(cps)
                elif k == NONDET:
                    cps.append([GEN, len(trail), p.fn(self, args), nxt])
                    cont = backtrack(cps)
                else:
                    if type(name) is tuple:
                        name = name[0]
                    if name == ",":
                        cont = (args[0], cutb, (args[1], cutb, nxt))
                    elif name == "$cut":  # the end of an if-then-else's condition
                        del cps[args[0] :]
                        cont = nxt
                    else:
                        cont = run_control(self, name, args, cutb, nxt, cps)
                        if cont is FAIL:
                            cont = backtrack(cps)
        except PrologError:
            raise
        except Exception as err:  # a built-in's own failure: make it a Prolog error
            raise host_error(err, goal) from err
        finally:
            if running:
                pacer.leave()

    def _call_clauses(self, p: Pred, args: Value, nxt: Cont, cps: list[ChoicePoint]) -> Cont:
        """Try the clauses of `p` that the first argument selects; False when none runs.

        A clause ending in a call to its own predicate returns that call's arguments as a
        list: loop here instead of going round the goal dispatch.
        """
        trail = self.trail
        loops = 0
        every = self.budget.interval()
        while True:
            if not cps and trail:
                del trail[:]
            loops += 1
            if loops >= every:  # a deterministic self-recursion loops here
                every = self.budget.spend(loops)
                loops = 0
            cands = p.store
            lo = p.head
            if len(cands) - lo > 1 and args:
                first = args[0]
                while type(first) is Var and first.ref is not None:
                    first = first.ref
                if type(first) is Term:
                    index = p.index
                    if index is None:
                        index = p.build_index()
                    cands = index.get((first[0], len(first[1])), p.varclauses)
                    lo = 0
                elif type(first) is not Var:
                    index = p.index
                    if index is None:
                        index = p.build_index()
                    if index:  # some clause has a constant first argument
                        t = type(first)
                        if t is int or t is str:
                            cands = index.get(first, p.varclauses)
                        else:
                            cands = p.candidates(first)
                        lo = 0
            if p.erased:
                cands = p.live(cands[lo:])
                lo = 0
            n = len(cands)
            if n == lo:
                return False
            cl = cands[lo]
            cb = len(cps)
            if n - lo > 1:
                cps.append([CLAUSES, len(trail), args, nxt, cands, lo + 1, n, p])
            run = cl.run
            if run is None or self.occurs_check != "false":
                run = self.clause_runner(cl)
            cont = run(args, trail, cb, nxt, cps)
            if type(cont) is not list:
                return cont
            args = cont

    def _backtrack(self, cps: list[ChoicePoint]) -> Cont:
        """Resume the newest choicepoint; return its continuation, or False when none is left."""
        trail = self.trail
        while cps:
            cp = cps[-1]
            mark = cp[1]
            n = len(trail) - mark  # taken once: a long trail's length is a new int each time
            if n > 8:  # a long undo: one pass over a slice beats popping
                for v in trail[mark:]:
                    v.ref = None
                del trail[mark:]
            else:
                while n:
                    trail.pop().ref = None
                    n -= 1
            kind = cp[0]
            if kind == PROC:  # the commonest: a compiled procedure's later clauses
                cps.pop()
                cont = cp[4](cp[2], trail, cp[3], cps, cp[5])
                if type(cont) is list:
                    cont = self._again(cp[4], cont, cp[3], cps)
                if cont is not False:
                    return cont
            elif kind == CLAUSES:
                cont = self._next_clause(cp, cps)
                if cont is not False:
                    return cont
            elif kind == GEN:
                found = next(cp[2], None)
                if found is not None:
                    if found is False:  # the built-in's last solution: no choicepoint left
                        cps.pop()
                    return cp[3]
                cps.pop()
            elif kind == ALT:
                cps.pop()
                return cp[2]
            elif kind == BARRIER:
                return False
            else:
                if kind == REACT:
                    cp[2][6] = True
                cps.pop()
        return False

    def _again(self, proc: Procedure, args: list[Value], nxt: Cont, cps: list[ChoicePoint]) -> Cont:
        """Finish a call that a procedure handed back (see procedure.py).

        After PROC_LOOPS loops: count them and call the procedure again. With a Scan:
        run the clauses one by one here (an unbound first argument of a long predicate).
        """
        while type(args) is list:
            scan = args.pop()
            if scan is not None:
                return self._call_clauses(scan.pred, args, nxt, cps)
            self.budget.spend(PROC_LOOPS)
            args = proc(args, self.trail, nxt, cps, 0)
        return args

    def _next_clause(self, cp: ChoicePoint, cps: list[ChoicePoint]) -> Cont:
        """Try the next candidate clause of a CLAUSES choicepoint (popping it at the last)."""
        i = cp[5]
        cl = cp[4][i]
        cb = len(cps) - 1
        i += 1
        if i >= cp[6]:
            cps.pop()
        else:
            cp[5] = i
        run = cl.run
        if run is None or self.occurs_check != "false":
            run = self.clause_runner(cl)
        cont = run(cp[2], self.trail, cb, cp[3], cps)
        if type(cont) is list:
            return (make_term((cp[7].name, tuple(cont))), 0, cp[3])
        return cont

    def _call_other(self, goal: Value, cutb: int, nxt: Cont) -> Cont:
        """Dispatch a goal that is a bound variable; raise for unbound or non-callable."""
        while type(goal) is Var:
            if goal.ref is None:
                raise PrologInstantiationError(
                    "a goal is an unbound variable; bind it before calling"
                )
            goal = goal.ref
        if type(goal) in (Term, str):
            return (goal, cutb, nxt)
        raise PrologTypeError("callable", goal, f"{goal!r} is not a callable goal")

    def _push_python(
        self, p: Pred, args: tuple[Value, ...], nxt: Cont, cps: list[ChoicePoint]
    ) -> None:
        """Try the Python predicate's solutions first, then the ordinary clauses."""
        trail = self.trail
        cands = p.clauses if not args or len(p.clauses) < 2 else p.candidates(deref1(args[0]))
        cands = p.live(cands)
        if cands:
            cps.append([CLAUSES, len(trail), args, nxt, cands, 0, len(cands), p])
        assert p.pyfn is not None
        cps.append([GEN, len(trail), python_solutions(self, p, args), nxt])


def host_error(err: Exception, goal: Value) -> PrologError:
    """The Prolog error for a Python exception raised while running `goal`."""
    while type(goal) is Var and goal.ref is not None:
        goal = goal.ref
    if type(goal) is tuple:
        if len(goal) != 3 or goal[2] not in MARKS:  # a Python tuple as a goal
            return PrologTypeError("callable", goal, f"{goal!r} is not a callable goal")
        where = f"{goal[0][0]}/{len(goal[1])}" if goal[2] is CALL else "an inline goal"
        if goal[2] is not CALL and goal[2] is not INLINE:
            where = "a control construct"
    elif type(goal) is Term:
        where = f"{goal[0]}/{len(goal[1])}"
    else:
        where = f"{goal}/0" if type(goal) is str else "the engine"
    if isinstance(err, RecursionError):
        return PrologResourceError(
            "term_depth", f"{where}: a term is nested too deeply for the engine ({err})"
        )
    if isinstance(err, MemoryError):
        return PrologResourceError("memory", f"{where}: out of memory")
    return PrologHostError(err, where)


def deref1(t: Value) -> Value:
    """Dereference (module-level for speed in the machine)."""
    while type(t) is Var:
        r = t.ref
        if r is None:
            return t
        t = r
    return t
