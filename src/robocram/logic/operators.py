"""Operator table: priorities and types (xfx, xfy, yfx, fy, fx) used by reader and writer."""

from __future__ import annotations

from robocram.logic.usage_errors import LogicArgumentError

__all__ = ["OperatorTable"]

_STANDARD: list[tuple[int, str, str]] = [
    (1200, "xfx", ":- -->"),
    (1200, "fx", ":- ?-"),
    (1150, "fx", "dynamic discontiguous initialization multifile table"),
    (1100, "xfy", "; |"),
    (1050, "xfy", "-> *->"),
    (1000, "xfy", ","),
    (990, "xfx", ":="),
    (900, "fy", "\\+"),
    (700, "xfx", "= \\= == \\== @< @> @=< @>= =.. is =:= =\\= < > =< >= >:< :< as"),
    (600, "xfy", ":"),
    (500, "yfx", "+ - /\\ \\/ xor"),
    (400, "yfx", "* / // mod rem << >> div rdiv divmod"),
    (200, "xfx", "**"),
    (200, "xfy", "^"),
    (200, "fy", "- + \\"),
    (100, "yfx", "."),
    (1, "fx", "$"),
]


class OperatorTable:
    """Prefix and infix operator definitions; each knowledge base owns a copy.

    >>> OperatorTable().infix["is"]
    (700, 'xfx')
    """

    def __init__(self) -> None:
        self.prefix: dict[str, tuple[int, str]] = {}
        self.infix: dict[str, tuple[int, str]] = {}
        for priority, kind, names in _STANDARD:
            for name in names.split():
                self.add(priority, kind, name)

    def add(self, priority: int, kind: str, name: str) -> None:
        """Define (or with priority 0 remove) an operator, as `op/3` does."""
        if kind not in ("xfx", "xfy", "yfx", "fy", "fx", "xf", "yf"):
            raise LogicArgumentError(f"operator type {kind!r} is not one of xfx, xfy, yfx, fy, fx")
        if not 0 <= priority <= 1200:
            raise LogicArgumentError(f"operator priority {priority} is outside 0..1200")
        table = self.prefix if kind in ("fy", "fx") else self.infix
        if priority == 0:
            table.pop(name, None)
        else:
            table[name] = (priority, kind)

    def copy(self) -> OperatorTable:
        """Return an independent copy."""
        other = OperatorTable.__new__(OperatorTable)
        other.prefix = dict(self.prefix)
        other.infix = dict(self.infix)
        return other
