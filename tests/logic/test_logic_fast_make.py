"""Variables and terms made without a Python frame (`make_var`, `make_term`) are the same
objects as `Var()` and `Term(name, args)` make."""

from __future__ import annotations

from robocram.logic import KnowledgeBase, Term, Var
from robocram.logic.functor_arg import fresh_vars
from robocram.logic.terms import make_term, make_var


def test_var_call_still_makes_an_unbound_variable() -> None:
    v = Var()
    assert type(v) is Var and v.ref is None
    fast = make_var()
    fast.ref = None
    assert type(fast) is Var and fast is not v


def test_fresh_vars_of_any_count_are_distinct_and_unbound() -> None:
    for n in (1, 3, 4, 9):
        made = fresh_vars(n)
        assert len({id(v) for v in made}) == n
        assert all(type(v) is Var and v.ref is None for v in made)


def test_clause_code_variables_unbound_until_bound() -> None:
    # Fresh variables of clause code (head structures, functor/3 of arity 5) read as
    # unbound: checked on the Python objects the answer holds, not by our own unify.
    kb = KnowledgeBase()
    kb.consult("mk(f(A, B), g(B, _)) :- A = 1.\nwide(T) :- functor(T, h, 5).")
    answer = kb.first("mk(X, Y)")
    assert answer is not None
    _, (one, b) = answer["X"]
    _, (b2, c) = answer["Y"]
    assert one == 1 and type(c) is Var and c.ref is None
    assert type(b) is Var and type(b2) is Var
    wide = kb.first("wide(T)")
    assert wide is not None
    args = wide["T"][1]
    assert len(args) == 5 and all(type(a) is Var for a in args)


def test_term_call_and_make_term_agree() -> None:
    made = Term("f", [1, "a"])  # any iterable of arguments, as before
    fast = make_term(("f", (1, "a")))
    assert type(made) is Term and type(fast) is Term
    assert made == fast and tuple.__eq__(made, ("f", (1, "a")))
    assert made.name == "f" and made.args == (1, "a") and made.arity == 2
    assert Term("g").args == ()
    assert made != ("f", (1, "a"))  # a plain tuple is not a term


def test_clause_code_terms_are_terms() -> None:
    kb = KnowledgeBase()
    kb.consult("wrap(X, box(X, [X])).")
    answer = kb.first("wrap(7, B)")
    assert answer is not None
    box = answer["B"]
    assert type(box) is Term and box[0] == "box" and box[1][0] == 7
    assert box[1][1] == [7]  # answers give Prolog lists as Python lists
