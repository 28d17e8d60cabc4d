"""Read Prolog text (clauses, queries) into engine terms with an operator-precedence parser."""

from __future__ import annotations

from collections.abc import Iterator

from robocram.logic.lexer import Token, syntax_error, tokenize
from robocram.logic.operators import OperatorTable
from robocram.logic.terms import NIL, PString, Term, Var, make_list, make_var
from robocram.logic.value import Value

__all__ = ["read_query", "read_terms"]

_STOP = frozenset([")", "]", "}", ",", "|"])


class _Parser:
    """Parse a token list; `varmap` maps variable names of the current clause to Vars."""

    def __init__(self, text: str, ops: OperatorTable, double_quotes: str = "string") -> None:
        self.text = text
        self.ops = ops
        self.double_quotes = double_quotes
        self.tokens = tokenize(text)
        self.i = 0
        self.varmap: dict[str, Var] = {}

    def peek(self) -> Token:
        return self.tokens[self.i]

    def next(self) -> Token:
        tok = self.tokens[self.i]
        self.i += 1
        return tok

    def fail(self, tok: Token, reason: str) -> Exception:
        return syntax_error(self.text, tok.pos, reason)

    def expect(self, value: str) -> None:
        tok = self.next()
        if tok.kind != "punct" or tok.value != value:
            raise self.fail(tok, f"expected '{value}'")

    def at_term_end(self) -> bool:
        tok = self.peek()
        return tok.kind in ("end", "eof") or (tok.kind == "punct" and tok.value in _STOP)

    def parse(self, max_prec: int) -> tuple[Value, int]:
        left, prec = self.primary(max_prec)
        return self.infix(left, prec, max_prec)

    def infix(self, left: Value, left_prec: int, max_prec: int) -> tuple[Value, int]:
        while True:
            tok = self.peek()
            if tok.kind == "atom" or (tok.kind == "punct" and tok.value in (",", "|")):
                name = tok.value
            else:
                return left, left_prec
            spec = self.ops.infix.get(name)
            if spec is None:
                return left, left_prec
            prec, kind = spec
            left_max = prec if kind == "yfx" else prec - 1
            right_max = prec if kind == "xfy" else prec - 1
            if prec > max_prec or left_prec > left_max:
                return left, left_prec
            self.next()
            right, _ = self.parse(right_max)
            left = Term(";" if name == "|" else name, (left, right))
            left_prec = prec

    def primary(self, max_prec: int) -> tuple[Value, int]:
        tok = self.next()
        kind = tok.kind
        if kind == "num":
            return tok.value, 0
        if kind == "var":
            var = self.varmap.get(tok.value) if tok.value != "_" else None
            if var is None:
                var = make_var()
                var.ref = None
                if tok.value != "_":
                    self.varmap[tok.value] = var
            return var, 0
        if kind == "str":
            return self.quoted_text(tok.value), 0
        if kind == "bq":
            return make_list([ord(c) for c in tok.value]), 0
        if kind == "punct":
            return self.punct(tok)
        if kind in ("atom", "qatom"):
            return self.atom(tok, max_prec)
        if kind == "end":
            raise self.fail(tok, "unexpected end of clause")
        raise self.fail(tok, "unexpected end of text")

    def quoted_text(self, text: str) -> Value:
        """A double-quoted text as the `double_quotes` flag says: string, codes, chars, atom."""
        mode = self.double_quotes
        if mode == "codes":
            return make_list([ord(c) for c in text])
        if mode == "chars":
            return make_list(list(text))
        if mode == "atom":
            return text
        return PString(text)

    def punct(self, tok: Token) -> tuple[Value, int]:
        if tok.value == "(":
            term, _ = self.parse(1200)
            self.expect(")")
            return term, 0
        if tok.value == "[":
            if self.peek().kind == "punct" and self.peek().value == "]":
                self.next()
                return self.maybe_call(NIL), 0
            items = [self.parse(999)[0]]
            while self.peek().kind == "punct" and self.peek().value == ",":
                self.next()
                items.append(self.parse(999)[0])
            tail: Value = NIL
            if self.peek().kind == "punct" and self.peek().value == "|":
                self.next()
                tail = self.parse(999)[0]
            self.expect("]")
            return make_list(items, tail), 0
        if tok.value == "{":
            if self.peek().kind == "punct" and self.peek().value == "}":
                self.next()
                return self.maybe_call("{}"), 0
            term, _ = self.parse(1200)
            self.expect("}")
            return Term("{}", (term,)), 0
        raise self.fail(tok, f"unexpected '{tok.value}'")

    def maybe_call(self, name: str) -> Value:
        tok = self.peek()
        if tok.kind == "punct" and tok.value == "(" and not tok.layout_before:
            self.next()
            args = [self.parse(999)[0]]
            while self.peek().kind == "punct" and self.peek().value == ",":
                self.next()
                args.append(self.parse(999)[0])
            self.expect(")")
            return Term(name, args)
        return name

    def atom(self, tok: Token, max_prec: int) -> tuple[Value, int]:
        name = tok.value
        nxt = self.peek()
        if nxt.kind == "punct" and nxt.value == "(" and not nxt.layout_before:
            return self.maybe_call(name), 0
        if tok.kind == "atom" and name == "-" and nxt.kind == "num" and not nxt.layout_before:
            self.next()
            return -nxt.value, 0
        spec = self.ops.prefix.get(name) if tok.kind == "atom" else None
        if spec is None or self.at_term_end() or self.infix_follows():
            prec = max(self.ops.prefix.get(name, (0,))[0], self.ops.infix.get(name, (0,))[0])
            return name, (prec if prec <= max_prec else 0)
        prec, kind = spec
        if prec > max_prec:
            prec = 999
        arg, _ = self.parse(prec if kind == "fy" else prec - 1)
        return Term(name, (arg,)), prec

    def infix_follows(self) -> bool:
        tok = self.peek()
        if tok.kind != "atom" or tok.value not in self.ops.infix:
            return False
        if tok.value in self.ops.prefix:
            return False
        after = self.tokens[self.i + 1]
        return not (after.kind == "punct" and after.value == "(" and not after.layout_before)

    def clause(self) -> Value:
        self.varmap = {}
        term, _ = self.parse(1200)
        tok = self.next()
        if tok.kind != "end":
            raise self.fail(tok, "operator expected (missing '.' or ',' before this?)")
        return term


def read_terms(
    text: str, ops: OperatorTable | None = None, flags: dict[str, Value] | None = None
) -> Iterator[tuple[Value, dict[str, Var]]]:
    """Yield each clause of `text` with its variable names.

    The parser reads `flags` (a knowledge base's Prolog flags) before each clause, so a
    `:- set_prolog_flag(double_quotes, codes).` directive applies to the clauses after it.

    >>> [t for t, _ in read_terms("a. b :- c.")]
    ['a', b :- c]
    """
    parser = _Parser(text, ops or OperatorTable())
    while parser.peek().kind != "eof":
        if flags is not None:
            parser.double_quotes = flags.get("double_quotes", "string")
        term = parser.clause()
        yield term, parser.varmap


def read_query(
    text: str, ops: OperatorTable | None = None, flags: dict[str, Value] | None = None
) -> tuple[Value, dict[str, Var]]:
    """Read one term (the final '.' is optional) and its variables by name.

    >>> read_query("X = f(Y)")[0].name
    '='
    """
    stripped = text.rstrip()
    if not stripped.endswith(".") or stripped.endswith(".."):
        text = text + " ."
    quotes = "string" if flags is None else flags.get("double_quotes", "string")
    parser = _Parser(text, ops or OperatorTable(), quotes)
    if parser.peek().kind == "eof":
        raise parser.fail(parser.peek(), "empty query")
    term = parser.clause()
    if parser.peek().kind != "eof":
        raise parser.fail(parser.peek(), "text after the end of the query")
    return term, parser.varmap
