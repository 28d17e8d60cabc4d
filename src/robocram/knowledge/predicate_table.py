"""The predicate table: every predicate robocram's own code asks or provides, once.

Rows by source live in ``robot_predicates.py`` (description facts), ``world_predicates.py``
(computed by the world), ``grasp_predicates.py`` (computed by the grasp model),
``scene_predicates.py`` (scene facts) and ``reasoning_predicates.py`` (the costmaps'
reach reasoning); this module collects them. The table is the
library's contract: users may still query the knowledge base in Prolog.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

from robocram.knowledge.grasp_predicates import GRASP_PREDICATES
from robocram.knowledge.predicate import Predicate, Source
from robocram.knowledge.reasoning_predicates import REASONING_PREDICATES
from robocram.knowledge.robot_predicates import DESCRIPTION_PREDICATES
from robocram.knowledge.scene_predicates import SCENE_PREDICATES
from robocram.knowledge.world_predicates import WORLD_PREDICATES

PREDICATE_TABLE: Mapping[str, Predicate[Any]] = MappingProxyType(
    {
        p.indicator: p
        for p in (
            *DESCRIPTION_PREDICATES,
            *WORLD_PREDICATES,
            *GRASP_PREDICATES,
            *SCENE_PREDICATES,
            *REASONING_PREDICATES,
        )
    }
)


def predicates_of(source: Source) -> tuple[Predicate[Any], ...]:
    """The table's predicates ``source`` provides, in table order."""
    return tuple(p for p in PREDICATE_TABLE.values() if p.source is source)


def indicators_of(source: Source) -> tuple[str, ...]:
    """The sorted ``name/arity`` of the predicates ``source`` provides."""
    return tuple(sorted(p.indicator for p in predicates_of(source)))
