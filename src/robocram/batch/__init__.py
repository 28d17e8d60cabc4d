"""Batch projection: one plan run many ways (objects moved, robots swapped, parameters
changed), each variant in a world restored between runs, across worker processes.

``project_variants(variants, plan, robot=..., workers=2)`` streams a
:class:`VariantResult` per variant as it finishes: success, the failure, the time, what the
plan chose. A variant is plain data with a seed, so its result does not depend on the worker.
"""

from robocram.batch.batch_run import BatchRun
from robocram.batch.errors import BackendMissing, BadVariant, BatchError, UnknownBackend
from robocram.batch.project_variants import BACKENDS, project_variants
from robocram.batch.result import VariantResult, VariantStatus
from robocram.batch.variant import Variant

__all__ = [
    "BACKENDS",
    "BackendMissing",
    "BadVariant",
    "BatchError",
    "BatchRun",
    "UnknownBackend",
    "Variant",
    "VariantResult",
    "VariantStatus",
    "project_variants",
]
