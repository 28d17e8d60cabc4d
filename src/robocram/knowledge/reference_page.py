"""``docs/predicates.md``, written from the predicate table.

Run ``python -m robocram.knowledge.reference_page > docs/predicates.md`` after changing
the table; ``tests/knowledge/test_knowledge_reference_page.py`` fails while the page is
stale.
"""

from __future__ import annotations

from robocram.knowledge.predicate import Need, Predicate, Source
from robocram.knowledge.predicate_table import predicates_of

_HEADINGS = {
    Source.DESCRIPTION: "Facts a robot description provides",
    Source.WORLD: "Computed by the world",
    Source.GRASPING: "Computed by the grasp model",
    Source.SCENE: "Facts a scene provides",
    Source.REASONING: "Computed by the costmaps' reach reasoning",
}
_INTRO = """# Predicates

Generated from the predicate table (`src/robocram/knowledge/`) by
`python -m robocram.knowledge.reference_page > docs/predicates.md`; do not edit by hand.

Every predicate robocram's own code asks or provides, with its arguments (name: Python
type [unit]). Plans ask them through typed queries (`ROBOT_TOOL_FRAME.first(kb,
robot="pr2", arm="left") -> ArmFrame`), which return frozen dataclasses with one field per
argument; users may still query them in Prolog. World predicates take the world first,
bound by `world(W)`.
"""


def _argument_text(p: Predicate[object]) -> str:
    parts = []
    for a in p.arguments:
        unit = f" [{a.unit}]" if a.unit else ""
        parts.append(f"`{a.variable}`: {a.type_text}{unit}")
    return ", ".join(parts)


def _row(p: Predicate[object]) -> str:
    need = "" if p.need is Need.OPTIONAL else f" Required for {p.need.value}."
    return f"| `{p.indicator}` | {_argument_text(p)} | {p.meaning}.{need} |"


def reference_page() -> str:
    """The text of ``docs/predicates.md``."""
    lines = [_INTRO]
    for source, heading in _HEADINGS.items():
        lines += [f"## {heading}", "", "| predicate | arguments | meaning |", "|---|---|---|"]
        lines += [_row(p) for p in predicates_of(source)]
        lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    print(reference_page(), end="")
