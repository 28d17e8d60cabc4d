"""Integer functions compiled to Python operators give ISO's values and errors.

The expected values are computed here from the ISO definitions (truncating `//` and
`rem`, flooring `div` and `mod`), not by the engine's arithmetic.
"""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase, PrologEvaluationError, PrologTypeError
from robocram.logic.value import Value

OPS = ["//", "rem", "mod", "div", ">>", "/\\", "\\/", "xor", "min", "max"]
NUMBERS = [-7, -3, -1, 0, 1, 2, 5, 7, 2**70 + 3]


def _trunc_div(a: int, b: int) -> int:
    q = abs(a) // abs(b)
    return q if (a < 0) == (b < 0) else -q


def expected(op: str, a: int, b: int) -> int | None:
    """ISO's value of `a op b`; None where it raises."""
    if op in ("//", "rem", "mod", "div") and b == 0:
        return None
    if op == ">>" and b < 0:
        return a << -b
    values = {
        "//": lambda: _trunc_div(a, b),
        "rem": lambda: a - b * _trunc_div(a, b),
        "mod": lambda: a - b * (a // b),
        "div": lambda: (a - a % b) // b,
        ">>": lambda: a >> b,
        "/\\": lambda: a & b,
        "\\/": lambda: a | b,
        "xor": lambda: a ^ b,
        "min": lambda: min(a, b),
        "max": lambda: max(a, b),
    }
    return values[op]()


def one(kb: KnowledgeBase, text: str) -> dict[str, Value]:
    """The first answer of `text`."""
    return next(iter(kb.query(text)))


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    k = KnowledgeBase()
    clauses = [f"f({i}, X, Y, Z) :- Z is {op}(X, Y)." for i, op in enumerate(OPS)]
    # the same in the test of an if-then-else's condition
    clauses += [
        f"g({i}, X, Y, Z) :- ( {op}(X, Y) >= 0 -> Z = pos ; Z = neg )." for i, op in enumerate(OPS)
    ]
    k.consult("\n".join(clauses))
    return k


@pytest.mark.parametrize("op", OPS)
def test_integer_functions_give_iso_values(kb: KnowledgeBase, op: str) -> None:
    i = OPS.index(op)
    for a in NUMBERS:
        for b in [n for n in NUMBERS if not (op == ">>" and abs(n) > 64)]:
            want = expected(op, a, b)
            for _ in range(4):  # the clause, then the procedure compiled after a few calls
                if want is None:
                    with pytest.raises(PrologEvaluationError):
                        one(kb, f"f({i}, {a}, {b}, Z)")
                    continue
                assert one(kb, f"f({i}, {a}, {b}, Z)")["Z"] == want, (op, a, b)
                got = one(kb, f"g({i}, {a}, {b}, Z)")["Z"]
                assert got == ("pos" if want >= 0 else "neg"), (op, a, b)


def test_floats_and_unbound_keep_their_errors(kb: KnowledgeBase) -> None:
    for _ in range(4):
        with pytest.raises(PrologTypeError):
            one(kb, "f(2, 2.5, 2, Z)")  # mod of a float
        assert one(kb, "f(8, 2.5, 2, Z)")["Z"] == 2  # min of mixed numbers
        assert one(kb, "f(9, 2.5, 2, Z)")["Z"] == 2.5
