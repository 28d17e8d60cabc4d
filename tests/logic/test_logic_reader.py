"""Reading Prolog text: operators, lists, quoting, strings, comments, syntax errors."""

from __future__ import annotations

import pytest

from robocram.logic import PrologSyntaxError, Term
from robocram.logic.reader import read_query, read_terms
from robocram.logic.terms import PString, format_term


def text(source: str) -> str:
    return format_term(read_query(source)[0], quoted=True)


def test_operators_follow_priority_and_associativity() -> None:
    assert text("a :- b, c ; d -> e") == "a :- b,c;d -> e"
    # ground: a variable's printed name comes from its id, which may or may not be reused
    assert text("1 - 2 - 3") == text("(1 - 2) - 3") == "1-2-3"
    assert read_query("1 - 2 - 3")[0].args[0] == Term("-", (1, 2))
    assert text("2 ^ 3 ^ 4") == "2^3^4" and read_query("2 ^ 3 ^ 4")[0].args[0] == 2
    assert read_query("- 1")[0] == Term("-", (1,)) and read_query("-1")[0] == -1
    assert read_query("\\+ a")[0] == Term("\\+", ("a",))
    assert read_query("f(a, (b, c))")[0].args[1] == Term(",", ("b", "c"))


def test_atoms_numbers_strings_and_lists() -> None:
    term = read_query("f('It''s', \"str\", 0'a, 0x1F, 1.5e3, [1, 2 | T], [], {x})")[0]
    args = term.args
    assert args[0] == "It's" and args[1] == PString("str") and args[2] == 97
    assert args[3] == 31 and args[4] == 1500.0
    assert format_term(args[5]).startswith("[1,2|_G") and args[6] == "[]"
    assert args[7] == Term("{}", ("x",))
    assert read_query("'\\n'")[0] == "\n"


def test_comments_and_clause_sequence() -> None:
    source = "% line comment\na(1). /* block\ncomment */ b(X) :- a(X).\n"
    terms = [t for t, _ in read_terms(source)]
    assert terms[0] == Term("a", (1,)) and terms[1].name == ":-"


def test_variables_are_shared_by_name_within_a_clause() -> None:
    term, names = read_query("f(X, Y, X, _, _)")
    assert sorted(names) == ["X", "Y"]
    assert term.args[0] is term.args[2] and term.args[3] is not term.args[4]


@pytest.mark.parametrize(
    ("source", "line", "col"),
    [("a(1).\nb(2 .\n", 2, 5), ("ok.\n  f(x,, y).", 2, 7), ("p :- 'unterminated.", 1, 6)],
)
def test_syntax_errors_report_position(source: str, line: int, col: int) -> None:
    with pytest.raises(PrologSyntaxError) as info:
        list(read_terms(source))
    assert (info.value.line, info.value.column) == (line, col)
    assert info.value.text
