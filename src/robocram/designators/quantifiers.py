"""The CRAM way to write designators: ``a.motion(...)``, ``an.action(...)``, ``all_.objects(...)``.

``a`` and ``an`` are the same stateless builder (English picks the article); ``all_``
builds designators quantified over every entity that fits the description.
"""

from __future__ import annotations

from typing import Any

from robocram.designators.designator import Quantifier
from robocram.designators.grounded_designator import ActionDesignator, MotionDesignator
from robocram.designators.location_designator import LocationDesignator
from robocram.designators.object_designator import HumanDesignator, ObjectDesignator
from robocram.designators.properties import PropertyPair


class Singular:
    """Builds designators for one entity: ``a.location(pose=p)``, ``an.object(type="cup")``."""

    def action(self, *pairs: PropertyPair, **properties: Any) -> ActionDesignator:
        """Describe an action, grounded to a plan by ``action_grounding/2``."""
        return ActionDesignator(*pairs, **properties)

    def motion(self, *pairs: PropertyPair, **properties: Any) -> MotionDesignator:
        """Describe a motion, grounded to a command by ``motion_grounding/2``."""
        return MotionDesignator(*pairs, **properties)

    def location(self, *pairs: PropertyPair, **properties: Any) -> LocationDesignator:
        """Describe a place, resolved by location generators and validators."""
        return LocationDesignator(*pairs, **properties)

    def object(self, *pairs: PropertyPair, **properties: Any) -> ObjectDesignator:
        """Describe a thing, filled in by perception."""
        return ObjectDesignator(*pairs, **properties)

    def human(self, *pairs: PropertyPair, **properties: Any) -> HumanDesignator:
        """Describe a person, filled in by perception."""
        return HumanDesignator(*pairs, **properties)


class Universal:
    """Builds designators for every entity that fits: ``all_.objects(type="cup")``."""

    def objects(self, *pairs: PropertyPair, **properties: object) -> ObjectDesignator:
        """Describe all things that fit."""
        return ObjectDesignator(*pairs, quantifier=Quantifier.ALL, **properties)

    def humans(self, *pairs: PropertyPair, **properties: object) -> HumanDesignator:
        """Describe all people that fit."""
        return HumanDesignator(*pairs, quantifier=Quantifier.ALL, **properties)

    def locations(self, *pairs: PropertyPair, **properties: object) -> LocationDesignator:
        """Describe all places that fit."""
        return LocationDesignator(*pairs, quantifier=Quantifier.ALL, **properties)


a = Singular()
an = a
all_ = Universal()
