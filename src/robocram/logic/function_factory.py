"""Generated functions that read their constants as globals, not as closure cells.

CPython 3.11 copies every closure cell of a function into its frame on each call and
drops them on return, about 3 ns per cell per call whether the call reads it or not. A
procedure's constants (functors, atoms, key tables) were such cells: boyer's `equal/2`
holds 477 and ran 38,000 calls per iteration, a sixth of the program's time in that copy
alone. A global costs nothing per call and is read about as fast as a cell.

Each built function gets its own globals (the namespace, `k0`, `k1`, ... and its own
name, for a procedure that pushes itself as a choicepoint) and its own copy of the code
object: the interpreter caches global lookups per code object, keyed by the dictionary,
so one code object shared by several dictionaries would miss that cache at each switch.

>>> make = FunctionFactory(compile("def f(x):\\n    return x * k0 + k1\\n", "<g>", "exec"), "f", {})
>>> make(3, 1)(2), make(10, 0)(2)
(7, 20)
"""

from __future__ import annotations

from collections.abc import Callable
from types import CodeType, FunctionType

from robocram.logic.value import Value

__all__ = ["FunctionFactory", "constant_names"]

_NAMES: list[str] = []


def constant_names(n: int) -> list[str]:
    """`k0` ... `k{n-1}`: the global names of a generated function's constants."""
    while len(_NAMES) < n:
        _NAMES.append(f"k{len(_NAMES)}")
    return _NAMES[:n]


class FunctionFactory:
    """Builds function `name` of compiled module code, given the values of its constants."""

    __slots__ = ("code", "name", "namespace")

    def __init__(self, module: CodeType, name: str, namespace: dict[str, object]) -> None:
        scope = dict(namespace)
        exec(module, scope)  # noqa: S102 - generated clause code, see codegen.py
        fn = scope.pop(name)
        assert isinstance(fn, FunctionType)  # the source defines it: codegen writes it so
        self.code: CodeType = fn.__code__
        self.name = name
        self.namespace = scope

    def __call__(self, *consts: Value) -> Callable[..., object]:
        scope = dict(self.namespace)
        scope.update(zip(constant_names(len(consts)), consts, strict=True))
        fn = FunctionType(self.code.replace(), scope, self.name)
        scope[self.name] = fn
        return fn
