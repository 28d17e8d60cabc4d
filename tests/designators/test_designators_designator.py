"""Designator data model: properties, descriptions, chains, object data."""

from __future__ import annotations

import pytest

from robocram.designators import (
    DesignatorError,
    DesignatorPropertyError,
    GroundingError,
    Kind,
    LocationDesignator,
    MotionDesignator,
    ObjectDesignator,
    Quantifier,
    a,
    all_,
    an,
    desig_equal,
)


def test_keywords_become_ordered_properties_and_none_is_left_out() -> None:
    d = a.motion(type="looking", frame=None, direction="forward")
    assert isinstance(d, MotionDesignator) and d.kind is Kind.MOTION
    assert d.properties == (("type", "looking"), ("direction", "forward"))
    assert d.get("frame") is None and d.type == "looking"


def test_repeated_properties_are_given_as_pairs_first() -> None:
    d = a.location(("near", "sink"), ("near", "oven"), on="counter")
    assert d.get_all("near") == ["sink", "oven"]
    assert d.properties[-1] == ("on", "counter")


def test_description_reads_like_cram_and_nests() -> None:
    d = a.motion(type="looking", target=a.location(pose=(1, 2, 0)))
    assert d.description == "(a motion (type looking) (target (a location (pose (1, 2, 0)))))"
    assert an.object(type="bottle").description == "(an object (type bottle))"
    assert all_.objects(type="cup").description == "(all objects (type cup))"
    assert all_.objects(type="cup").quantifier is Quantifier.ALL


def test_motion_without_type_is_refused_with_a_fix() -> None:
    with pytest.raises(DesignatorPropertyError, match="needs a string 'type'.*a.motion"):
        a.motion(speed=1)


def test_malformed_keys_and_pairs_are_refused() -> None:
    with pytest.raises(DesignatorPropertyError, match="not a \\(key, value\\) pair"):
        a.location(("near", "sink", "oven"))  # type: ignore[arg-type]
    with pytest.raises(DesignatorPropertyError, match="not an identifier"):
        a.location(("joint-angle", 1))


def test_equate_builds_a_chain_with_first_and_current() -> None:
    wanted = an.object(type="bottle")
    seen = an.object(type="bottle", colour="red")
    later = an.object(type="bottle", colour="red", name="b1")
    wanted.equate(seen)
    seen.equate(later)
    assert wanted.first_desig() is wanted and later.first_desig() is wanted
    assert wanted.current_desig() is later
    assert wanted.chain() == [wanted, seen, later]
    assert desig_equal(wanted, later) and not desig_equal(wanted, an.object(type="bottle"))


def test_equate_refuses_other_kinds_and_foreign_chains() -> None:
    with pytest.raises(DesignatorError, match="only be equated with another one"):
        an.object(type="x").equate(a.location(pose=(0, 0, 0)))  # type: ignore[arg-type]
    first, other, shared = an.object(type="x"), an.object(type="x"), an.object(type="x")
    other.equate(shared)
    with pytest.raises(DesignatorError, match="already follows"):
        first.equate(shared)


def test_object_reference_is_its_perceived_data() -> None:
    wanted = an.object(type="bottle")
    with pytest.raises(GroundingError, match="no perceived data.*detecting"):
        wanted.reference()
    found = wanted.make_effective({"name": "bottle_1"}, pose=(1.0, 0.5, 0.8))
    assert isinstance(found, ObjectDesignator) and found.effective
    assert found.reference() == {"name": "bottle_1"}
    assert found.get("type") == "bottle" and found.get("pose") == (1.0, 0.5, 0.8)
    assert wanted.current_desig() is found and desig_equal(found, wanted)
    with pytest.raises(GroundingError, match="use current_desig"):
        wanted.reference()
    assert found.next_solution() is None


def test_location_with_a_pose_references_it_and_then_runs_out() -> None:
    loc = a.location(("pose", (1, 2, 0)), ("pose", (3, 4, 0)))
    assert isinstance(loc, LocationDesignator)
    assert loc.reference() == (1, 2, 0)
    second = loc.next_solution()
    assert second is not None and second.reference() == (3, 4, 0)
    assert second.next_solution() is None
    assert loc.current_desig() is second and list(loc.solutions()) == [(1, 2, 0), (3, 4, 0)]
    assert loc.next_solution() is second  # asked again: the same designator, no new one


def test_location_without_solution_names_generators() -> None:
    with pytest.raises(GroundingError, match="generators \\['pose_property'\\]"):
        a.location(on="table").reference()
