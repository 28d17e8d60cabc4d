"""Designators: symbolic descriptions of actions, motions, locations, objects and humans.

Written the way CRAM reads: ``a.motion(type="looking", target=a.location(pose=p))``,
``an.object(type="bottle")``, ``all_.objects(type="cup")``. Motions and actions are
grounded by Prolog rules (``motion_grounding/2``, ``action_grounding/2``), locations by
generators and validators, objects by perception. ``reference()`` takes the first
solution and caches it; ``next_solution()`` returns a designator for the next one.
"""

from robocram.designators.common_motions import install_common_motions, install_motion_family
from robocram.designators.designator import Designator, Kind, Quantifier, desig_equal
from robocram.designators.errors import (
    DesignatorArgumentError,
    DesignatorError,
    DesignatorPropertyError,
    DesignatorUnknownKey,
    DesignatorUsageError,
    GroundingError,
    MotionPropertyError,
)
from robocram.designators.grounded_designator import (
    ActionDesignator,
    MotionDesignator,
    bound_kb,
    grounded_types,
)
from robocram.designators.location_designator import LocationDesignator
from robocram.designators.location_resolver import (
    LocationResolver,
    Verdict,
    current_location_resolver,
    scoped_location_generator,
    scoped_location_validator,
    using_location_resolver,
)
from robocram.designators.motion_table import MOTION_TYPES, SIDES, motion_types
from robocram.designators.motion_type import (
    Answer,
    Atom,
    Command,
    MotionProperty,
    MotionType,
    commands_of,
)
from robocram.designators.object_designator import HumanDesignator, ObjectDesignator
from robocram.designators.prolog_access import install_designator_predicates
from robocram.designators.quantifiers import a, all_, an

__all__ = [
    "ActionDesignator",
    "Answer",
    "Atom",
    "Command",
    "Designator",
    "DesignatorArgumentError",
    "DesignatorError",
    "DesignatorPropertyError",
    "DesignatorUnknownKey",
    "DesignatorUsageError",
    "GroundingError",
    "HumanDesignator",
    "Kind",
    "LocationDesignator",
    "LocationResolver",
    "MOTION_TYPES",
    "MotionDesignator",
    "MotionProperty",
    "MotionPropertyError",
    "MotionType",
    "ObjectDesignator",
    "Quantifier",
    "SIDES",
    "Verdict",
    "a",
    "all_",
    "an",
    "bound_kb",
    "commands_of",
    "current_location_resolver",
    "desig_equal",
    "grounded_types",
    "install_common_motions",
    "install_designator_predicates",
    "install_motion_family",
    "motion_types",
    "scoped_location_generator",
    "scoped_location_validator",
    "using_location_resolver",
]
