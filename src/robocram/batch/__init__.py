"""Batch projection: one plan run many ways (objects moved, robots swapped, parameters
changed), each variant in a world restored between runs, across worker processes or Ray.

``project_variants(variants, plan, robot=..., workers=2, backend="processes")`` streams a
:class:`VariantResult` per variant as it finishes: success, the failure, the time, what the
plan chose. A variant is plain data with a seed, so its result does not depend on the worker
or the backend. ``load_spec`` reads the YAML/JSON specs of ``robocram batch``.
"""

from robocram.batch.batch_run import BatchRun
from robocram.batch.batch_spec import BatchSpec, load_spec
from robocram.batch.batch_summary import BatchSummary
from robocram.batch.errors import (
    BackendMissing,
    BadSpec,
    BadVariant,
    BatchError,
    UnguardedBatch,
    UnknownBackend,
)
from robocram.batch.project_variants import BACKENDS, project_variants
from robocram.batch.result import VariantResult, VariantStatus
from robocram.batch.variant import Variant

__all__ = [
    "BACKENDS",
    "BackendMissing",
    "BadSpec",
    "BadVariant",
    "BatchError",
    "BatchRun",
    "BatchSpec",
    "BatchSummary",
    "UnguardedBatch",
    "UnknownBackend",
    "Variant",
    "VariantResult",
    "VariantStatus",
    "load_spec",
    "project_variants",
]
