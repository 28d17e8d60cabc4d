"""Motion and action designators: grounded by Prolog rules in a knowledge base.

``motion_grounding(Desig, Command)`` turns a motion designator into a command term such
as ``move_base(Pose)``; ``action_grounding(Desig, Plan)`` turns an action designator into
a plan. The knowledge base is the one given to ``reference(kb=...)`` or else the current
one (``robocram.logic.current_kb()``, bound by an environment). Solutions are the lazy
answers of that query, one per grounding.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import ClassVar

from robocram.designators.designator import Designator, Kind, S_co
from robocram.designators.errors import (
    DesignatorPropertyError,
    DesignatorUsageError,
    GroundingError,
)
from robocram.designators.motion_table import MOTION_TYPES
from robocram.designators.motion_type import (
    check_known_keys,
    check_property_types,
    missing_property_error,
)
from robocram.logic import KnowledgeBase, PrologError, Term, current_kb


def bound_kb() -> KnowledgeBase | None:
    """Return the current knowledge base, or None when no ``using_kb`` block is active."""
    try:
        return current_kb()
    except PrologError:
        return None


class GroundedDesignator(Designator[S_co]):
    """A designator whose solutions are the answers of ``<predicate>(Desig, Solution)``."""

    grounding_predicate: ClassVar[str]

    def _check(self) -> None:
        if not isinstance(self.type, str):
            raise DesignatorPropertyError(
                f"{self.description} needs a string 'type' property, got {self.type!r}; "
                f'write e.g. a.{self.kind.value}(type="going", ...)',
                key="type",
                designator=self,
            )

    def _resolution_context(self, kb: KnowledgeBase | None) -> KnowledgeBase:
        if kb is not None:
            if not isinstance(kb, KnowledgeBase):
                raise DesignatorUsageError(f"kb must be a robocram.logic.KnowledgeBase, got {kb!r}")
            return kb
        bound = bound_kb()
        if bound is None:
            raise GroundingError(
                f"cannot ground {self.description}: no knowledge base given and none is "
                "current; pass reference(kb=...) or run inside an environment (with env: ...)",
                self,
            )
        return bound

    def _solutions(self, context: KnowledgeBase) -> Iterator[S_co]:
        for answer in context.query(f"{self.grounding_predicate}(D, G)", D=self):
            yield answer["G"]

    def _no_solution_error(self, context: KnowledgeBase) -> GroundingError:
        known = grounded_types(context, self.kind)
        if self.type in known:
            why = (
                f"the rules for type {self.type!r} did not match its other properties "
                f"{[k for k, _ in self.properties if k != 'type']}"
            )
        else:
            why = f"no {self.grounding_predicate} rule knows type {self.type!r}"
        return GroundingError(
            f"cannot ground {self.description}: {why}; types with {self.grounding_predicate} "
            f"rules: {list(known) or 'none (install a robot or environment)'}",
            self,
            grounded_types=known,
        )


class MotionDesignator(GroundedDesignator[Term]):
    """A low-level motion, e.g. ``(a motion (type looking) (target ...))``; grounds to a command.

    Motion types of the motion table (``MOTION_TYPES``) have their property types checked
    before grounding, and a missing property is named when no rule matched.
    """

    kind = Kind.MOTION
    grounding_predicate = "motion_grounding"

    def _solutions(self, context: KnowledgeBase) -> Iterator[Term]:
        motion = MOTION_TYPES.get(self.type)
        if motion is not None:
            check_property_types(motion, self)
        checked = motion is None
        for solution in super()._solutions(context):
            if not checked and motion is not None:
                check_known_keys(motion, self)
                checked = True
            yield solution

    def _no_solution_error(self, context: KnowledgeBase) -> GroundingError:
        motion = MOTION_TYPES.get(self.type)
        known = grounded_types(context, self.kind)
        if motion is not None and self.type in known:
            missing = missing_property_error(motion, self, known)
            if missing is not None:
                return missing
        return super()._no_solution_error(context)


class ActionDesignator(GroundedDesignator[object]):
    """A high-level action, e.g. ``(an action (type drawing) (shape house))``; grounds to a plan."""

    kind = Kind.ACTION
    grounding_predicate = "action_grounding"


def grounded_types(kb: KnowledgeBase, kind: Kind) -> tuple[str, ...]:
    """Return the ``type`` values that ``<kind>_grounding/2`` rules in ``kb`` test for.

    Found by running the grounding query on a probe designator whose ``desig_prop`` records
    every type a rule asks about and then fails, so no rule needs to list its types twice;
    rules that dispatch on the type they read list theirs in ``grounded_motion_type/1``.
    """
    probes: dict[Kind, tuple[str, type[TypeProbe]]] = {
        Kind.MOTION: (MotionDesignator.grounding_predicate, _MotionTypeProbe),
        Kind.ACTION: (ActionDesignator.grounding_predicate, _ActionTypeProbe),
    }
    if kind not in probes:
        return ()
    predicate, probe_class = probes[kind]
    probe = probe_class()
    for _ in kb.query(f"{predicate}(D, G)", D=probe):
        pass
    listed: list[str] = []
    if kind is Kind.MOTION and kb.defines("grounded_motion_type/1"):
        listed = [a["T"] for a in kb.query("grounded_motion_type(T)") if isinstance(a["T"], str)]
    return tuple(sorted({*probe.asked_types, *listed}))


def lists_motion_type(kb: KnowledgeBase, motion_type: str) -> bool:
    """Whether ``kb``'s grounding rules list ``motion_type`` in ``grounded_motion_type/1``:
    a family of motions installed for the robot only (``crouching`` for one on legs it
    bends), asked by plans that try it where it exists."""
    if not kb.defines("grounded_motion_type/1"):
        return False
    return any(a["T"] == motion_type for a in kb.query("grounded_motion_type(T)"))


class TypeProbe(Designator[None]):
    """A designator without properties that notes the types grounding rules ask for.

    ``desig_prop(Probe, type, T)`` records ``T`` and fails, so running a grounding query
    on a probe lists every type its rules test, without any rule naming its types twice.
    """

    def __init__(self) -> None:
        super().__init__()
        self.asked_types: list[str] = []

    def note(self, key: object, value: object) -> None:
        """Record the type a rule asked about."""
        if key == "type" and isinstance(value, str):
            self.asked_types.append(value)


class _MotionTypeProbe(TypeProbe):
    kind = Kind.MOTION


class _ActionTypeProbe(TypeProbe):
    kind = Kind.ACTION
