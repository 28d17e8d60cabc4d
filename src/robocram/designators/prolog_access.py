"""Prolog access to designators: the predicates grounding rules are written with.

``install_designator_predicates(kb)`` adds (idempotently):

- ``desig_prop(D, Key, Value)``: D has property Key = Value (enumerates when unbound)
- ``designator_grounding(D, G)``: G is a solution of D, lazily, in order
- ``designator_groundings(D, Gs)``: Gs lists D's solutions (at most ``GROUNDINGS_LIMIT``)
- kind tests ``action_desig/1``, ``motion_desig/1``, ``loc_desig/1``, ``obj_desig/1``,
  ``human_desig/1``, and ``desig_kind(D, Kind)`` (Kind: action, motion, location, ...)
- interface predicates ``motion_grounding(D, Command)`` and ``action_grounding(D, Plan)``:
  they fail until a robot or an environment extends them; ``grounded_motion_type(Type)``
  names the types of rules that do not test ``desig_prop(D, type, Type)`` themselves

Property keys are atoms (the Python keyword names); string values are atoms, designators
and poses are opaque objects, numbers and lists map as themselves.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

from robocram.designators.designator import Designator, Kind
from robocram.designators.errors import DesignatorArgumentError
from robocram.designators.grounded_designator import TypeProbe
from robocram.logic import KnowledgeBase, Var

GROUNDINGS_LIMIT = 100  # Prolog lists are finite; designator_grounding/2 streams them all
INTERFACE_GROUP = "designator_interface"
_KIND_TESTS = {
    "action_desig": Kind.ACTION,
    "motion_desig": Kind.MOTION,
    "loc_desig": Kind.LOCATION,
    "obj_desig": Kind.OBJECT,
    "human_desig": Kind.HUMAN,
}
_INTERFACE_TEXT = """
motion_grounding(_, _) :- fail.
action_grounding(_, _) :- fail.
grounded_motion_type(_) :- fail.
"""
INTERFACE_PREDICATES = ("motion_grounding/2", "action_grounding/2", "grounded_motion_type/1")


def install_designator_predicates(kb: KnowledgeBase) -> KnowledgeBase:
    """Add the designator predicates and grounding interface to ``kb``; return ``kb``."""
    _install_python_predicates(kb)
    if not all(kb.defines(p) for p in INTERFACE_PREDICATES):
        kb.consult(_INTERFACE_TEXT, group=INTERFACE_GROUP, extendable=INTERFACE_PREDICATES)
    return kb


def _install_python_predicates(kb: KnowledgeBase) -> None:
    @kb.predicate("desig_prop", 3)
    def desig_prop(d: object, key: object, value: object) -> Iterator[tuple[object, ...]]:
        if not isinstance(d, Designator):
            _require_bound(d, "desig_prop/3")
            return
        if isinstance(d, TypeProbe):
            d.note(key, value)
            return
        for k, v in d.properties:
            if isinstance(key, Var) or k == key:
                yield d, k, v

    @kb.predicate("designator_grounding", 2)
    def designator_grounding(d: object, solution: object) -> Iterator[tuple[object, ...]]:
        for current in _solutions(kb, d, "designator_grounding/2"):
            yield d, current

    @kb.predicate("designator_groundings", 2)
    def designator_groundings(d: object, solutions: object) -> Iterator[tuple[object, ...]]:
        found = _solutions(kb, d, "designator_groundings/2")
        yield d, list(itertools.islice(found, GROUNDINGS_LIMIT))

    @kb.predicate("desig_kind", 2)
    def desig_kind(d: object, kind: object) -> Iterator[tuple[object, ...]]:
        if isinstance(d, Designator):
            yield d, d.kind.value
        else:
            _require_bound(d, "desig_kind/2")

    for name, kind in _KIND_TESTS.items():
        _install_kind_test(kb, name, kind)


def _install_kind_test(kb: KnowledgeBase, name: str, kind: Kind) -> None:
    @kb.predicate(name, 1)
    def kind_test(d: object) -> Iterator[None]:
        if isinstance(d, Designator) and d.kind is kind:
            yield None
        elif not isinstance(d, Designator):
            _require_bound(d, f"{name}/1")


def _require_bound(d: object, predicate: str) -> None:
    if isinstance(d, Var):
        raise DesignatorArgumentError(
            f"{predicate} needs a designator as first argument, got an unbound variable"
        )


def _solutions(kb: KnowledgeBase, d: object, predicate: str) -> Iterator[object]:
    """Yield the solutions of designator ``d`` lazily, grounded in ``kb`` where it matters."""
    if not isinstance(d, Designator):
        _require_bound(d, predicate)
        return
    yield from d.solutions(None if d.kind is Kind.LOCATION else kb)
