"""Property: a random small URDF through ``add_urdf`` loads as ``RobotModel`` reads it, or
is refused with a typed error and the world unchanged; the process never dies (issue 24).

Trees, loops (a link given a second parent), crossed limits and four encodings are drawn.
``ROBOCRAM_PROPERTY_EXAMPLES=2000`` runs the long search; the quick run is derandomised.
"""

from __future__ import annotations

import os
import warnings
from dataclasses import dataclass

import pybullet
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from robocram.robots import RobotModel, UrdfError
from robocram.world import BodyLoadError, World

EXAMPLES = int(os.environ.get("ROBOCRAM_PROPERTY_EXAMPLES", "25"))
DOOR_SETTINGS = settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize="ROBOCRAM_PROPERTY_EXAMPLES" not in os.environ,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
ENCODINGS = ("utf-8", "latin-1 declared", "utf-16", "latin-1 undeclared")


@dataclass(frozen=True)
class Drawn:
    """A generated URDF: link ``i + 1`` hangs from ``parents[i]``; ``extra`` adds a parent."""

    parents: tuple[int, ...]
    kinds: tuple[str, ...]
    limits: tuple[tuple[float, float], ...]
    extra: tuple[int, int] | None  # (parent, child): a loop or a second parent
    accent: bool  # a non-ASCII link name
    encoding: str

    def text(self) -> str:
        names = [f"l{i}" for i in range(len(self.parents) + 1)]
        if self.accent:
            names[-1] = "pince_\xe9"
        links = "\n".join(f'<link name="{n}"/>' for n in names)
        joints = [
            self._joint(f"j{i}", names[p], names[i + 1], self.kinds[i], self.limits[i])
            for i, p in enumerate(self.parents)
        ]
        if self.extra is not None:
            parent, child = self.extra
            joints.append(self._joint("loop", names[parent], names[child], "fixed", (0, 0)))
        declared = self.encoding in ("latin-1 declared", "utf-16")
        name = {"utf-16": "UTF-16", "latin-1 declared": "ISO-8859-1"}.get(self.encoding, "")
        head = f'<?xml version="1.0" encoding="{name}"?>\n' if declared else ""
        return head + '<robot name="drawn">\n' + links + "\n" + "\n".join(joints) + "\n</robot>\n"

    @staticmethod
    def _joint(name: str, parent: str, child: str, kind: str, limit: tuple[float, float]) -> str:
        lower, upper = limit
        limit_tag = f'<limit lower="{lower}" upper="{upper}"/>' if kind != "fixed" else ""
        return (
            f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/><axis xyz="0 0 1"/>{limit_tag}</joint>'
        )

    def data(self) -> bytes:
        codec = {"utf-8": "utf-8", "utf-16": "utf-16"}.get(self.encoding, "latin-1")
        return self.text().encode(codec)


@st.composite
def drawn_urdfs(draw: st.DrawFn) -> Drawn:
    n = draw(st.integers(1, 5))
    parents = tuple(draw(st.integers(0, i)) for i in range(n))
    kinds = tuple(draw(st.sampled_from(("revolute", "prismatic", "fixed"))) for _ in range(n))
    bound = st.integers(-30, 30).map(lambda v: v / 10)
    limits = tuple((draw(bound), draw(bound)) for _ in range(n))
    extra = draw(st.none() | st.tuples(st.integers(0, n), st.integers(0, n)))
    return Drawn(
        parents, kinds, limits, extra, draw(st.booleans()), draw(st.sampled_from(ENCODINGS))
    )


@DOOR_SETTINGS
@given(drawn=drawn_urdfs())
def test_add_urdf_loads_what_the_parser_reads_or_refuses_cleanly(
    drawn: Drawn, tmp_path_factory: pytest.TempPathFactory
) -> None:
    path = tmp_path_factory.mktemp("door") / "drawn.urdf"
    path.write_bytes(drawn.data())
    try:
        model: RobotModel | None = RobotModel.from_file(path)
    except UrdfError:
        model = None
    with World() as world, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        world.add_box("box", (0.1, 0.1, 0.1))
        if model is None:
            with pytest.raises(BodyLoadError):
                world.add_urdf("drawn", path)
            assert [o.name for o in world.objects()] == ["box"]
            assert pybullet.getNumBodies(physicsClientId=world.physics.client()) == 1
            return
        world.add_urdf("drawn", path)
        assert set(world.link_names("drawn")) == set(model.links)
        assert set(world.joint_states("drawn")) == {j.name for j in model.movable_joints()}
        for joint in model.movable_joints():
            limits = world.bodies.joint_limits("drawn", joint.name)
            assert (limits.lower, limits.upper) == pytest.approx((joint.lower, joint.upper))


def test_the_drawn_cases_cover_refusals_and_loads() -> None:
    crossed = Drawn((0,), ("revolute",), ((1.0, -1.0),), None, False, "utf-8")
    looped = Drawn((0, 1), ("fixed", "fixed"), ((0, 0), (0, 0)), (2, 1), False, "utf-8")
    wide = Drawn((0,), ("revolute",), ((-1.0, 1.0),), None, True, "utf-16")
    for refused in (crossed, looped):
        with pytest.raises(UrdfError):
            RobotModel.from_string(refused.text())
    assert set(RobotModel.from_string(wide.text()).links) == {"l0", "pince_\xe9"}
