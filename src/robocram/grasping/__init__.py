"""Grasps from an object's geometry and a hand's size, the same for every robot.

:func:`grasps` lists the grasps (top, front, left, right, rim, handle; a suction hand's
side) a hand can take of
an object's shape; :func:`grasp_candidates` does so for an object in a world, with the
type's knowledge-base facts, best first and in the map; :func:`install_grasp_predicates`
opens them to plans as ``object_grasp/7`` (docs/grasping.md).
"""

from robocram.grasping.errors import GraspingError, ObjectUngraspable, UnknownGraspError
from robocram.grasping.grasp import Grasp
from robocram.grasping.grasp_model import CLEARANCE, GRASP_NAMES, grasps, tool_orientation
from robocram.grasping.grasp_predicates import install_grasp_predicates
from robocram.grasping.hand import Hand, approach_axis, hand_of, palm_hold
from robocram.grasping.object_grasps import (
    GraspCandidate,
    candidates_at,
    grasp_candidates,
    grasp_names,
    install_grasp_facts,
    object_shape,
)
from robocram.grasping.object_shape import ObjectShape, catalogue_shape, shape_of

__all__ = [
    "CLEARANCE",
    "GRASP_NAMES",
    "Grasp",
    "GraspCandidate",
    "GraspingError",
    "Hand",
    "ObjectShape",
    "ObjectUngraspable",
    "UnknownGraspError",
    "approach_axis",
    "candidates_at",
    "catalogue_shape",
    "grasp_candidates",
    "grasp_names",
    "grasps",
    "hand_of",
    "install_grasp_facts",
    "install_grasp_predicates",
    "object_shape",
    "palm_hold",
    "shape_of",
    "tool_orientation",
]
