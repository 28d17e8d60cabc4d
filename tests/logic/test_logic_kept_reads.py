"""Texts read in the standard syntax kept on disk: read back as the reader reads them, a
damaged entry read again from the text and replaced, texts with directives not kept."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.logic import KnowledgeBase
from robocram.logic.kept_reads import _decoded, _NotKept, keep_terms, kept_terms
from robocram.logic.reader import read_terms
from robocram.logic.shared_reads import STANDARD_SYNTAX
from robocram.logic.terms import PString, Term, Var
from robocram.logic.value import Value

TEXT = 'p(X, [a, 1.5, -3 | T], "s", f(X, _, _)) :- q(X, T), r(12345678901234567890).'


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path))
    return tmp_path / "prolog-terms"


def _shape(term: Value, numbers: dict[Var, int]) -> object:
    """The term with its variables numbered by first appearance (names are ids)."""
    if isinstance(term, Var):
        return ("var", numbers.setdefault(term, len(numbers)))
    if isinstance(term, Term):
        return (term[0], tuple(_shape(a, numbers) for a in term[1]))
    if isinstance(term, PString):
        return ("string", term.text)
    return (type(term).__name__, term)


def _read(text: str) -> list[Value]:
    return [term for term, _ in read_terms(text)]


def test_kept_terms_are_the_read_ones(cache: Path) -> None:
    assert kept_terms(TEXT) is None
    keep_terms(TEXT, _read(TEXT))
    kept = kept_terms(TEXT)
    assert kept is not None
    assert [_shape(t, {}) for t in kept] == [_shape(t, {}) for t in _read(TEXT)]
    head = kept[0][1][0]  # p(X, ...): the same variable X in the head and the body
    assert isinstance(head, Term) and head[1][0] is kept[0][1][1][1][0][1][0]


def test_a_damaged_entry_is_read_again_and_replaced(cache: Path) -> None:
    text = "d(1). d(2). e(X) :- d(X), X > 1."
    kb = KnowledgeBase()
    kb.consult(text, group="g")  # read, kept on disk
    (entry,) = cache.glob("*.terms")
    data = bytearray(entry.read_bytes())
    data[-3] ^= 0xFF  # one byte of the terms: the digest no longer matches
    entry.write_bytes(bytes(data))
    assert kept_terms(text) is None
    STANDARD_SYNTAX._texts.clear()  # as a new process: nothing read in memory
    fresh = KnowledgeBase()
    fresh.consult(text, group="g")
    assert [a["X"] for a in fresh.query("e(X)")] == [2]
    assert kept_terms(text) is not None  # written again, whole


def test_a_text_with_directives_is_not_kept(cache: Path) -> None:
    KnowledgeBase().consult(":- dynamic(c/1). c(1).", group="g")
    assert not list(cache.glob("*.terms"))


@pytest.mark.parametrize(
    "stored",
    [
        True,  # a bool: marshal keeps it, the encoder never writes one
        ("f", ["a"]),  # a compound's arguments as a list
        (1, ("a",)),  # a compound named by a number
        [1],  # a variable numbered 1 before any numbered 0
        {"a": 1},
    ],
)
def test_a_kept_value_the_encoder_never_writes_is_refused(stored: object) -> None:
    """Decoding tests exact types: what no clause encodes to is no term (the entry is then
    read again from its text)."""
    with pytest.raises(_NotKept):
        _decoded(("p", (stored,)), [])
