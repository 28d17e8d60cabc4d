"""Parsed robot models kept for the process, so every load of one URDF shares one model.

What a plan learns about a robot's kinematics (IK solvers, start tables, reach bounds,
link radii) is kept on its :class:`~robocram.robots.RobotModel`, which lives as long as the
model. Loading ``"pr2"`` for each new scene parsed the URDF again and so threw all of that
away: a user's first plan in each fresh scene paid ~0.1 s of caches again. Models are
immutable, so loads of the same file (same bytes, same package paths, same added frames
and boxes) share one; a changed file is parsed anew. At most :data:`MODELS_KEPT` are kept.
The process's memo is ``robocram.robots.robot_model.MODELS``.
"""

from __future__ import annotations

import hashlib
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Generic, TypeVar

from robocram.logic.lru import LRUCache
from robocram.robots.model_additions import BoxSpec, FrameSpec, JointCoupling

M = TypeVar("M")  # the model type (RobotModel, which keeps the process's memo)

MODELS_KEPT = 8  # different robot files a process loads (a few MB each with their caches)

ModelKey = tuple[
    str,
    str,
    tuple[Path, ...],
    tuple[FrameSpec, ...],
    tuple[BoxSpec, ...],
    bool,
    tuple[JointCoupling, ...],
]


class ModelMemo(Generic[M]):
    """The last :data:`MODELS_KEPT` models built, by the content of what they were built from."""

    def __init__(self, size: int = MODELS_KEPT) -> None:
        self.size = size
        self._models: LRUCache[ModelKey, tuple[M, list[warnings.WarningMessage]]] = LRUCache(size)

    def model(
        self,
        file: Path,
        package_paths: tuple[Path, ...],
        frames: tuple[FrameSpec, ...],
        boxes: tuple[BoxSpec, ...],
        build: Callable[[], M],
        lenient: bool = False,
        couplings: tuple[JointCoupling, ...] = (),
    ) -> M:
        """The model kept for ``file``'s current bytes and these additions, or ``build()``.

        ``lenient`` builds (boxes for missing packages) are kept apart from strict ones.
        A file that cannot be read is left to ``build`` to report. The warnings the build
        gave (a missing mesh) are given again on every load, as a parse would.
        """
        try:
            digest = hashlib.sha256(file.read_bytes()).hexdigest()
        except OSError:
            return build()
        key: ModelKey = (
            str(file.resolve()),
            digest,
            package_paths,
            frames,
            boxes,
            lenient,
            couplings,
        )
        found = self._models.get_or_build(key, lambda: _built(build))
        for w in found[1]:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, source=w.source)
        return found[0]

    def clear(self) -> None:
        """Forget every model (they live on while something else holds them)."""
        self._models.clear()


def _built(build: Callable[[], M]) -> tuple[M, list[warnings.WarningMessage]]:
    """``build()`` and the warnings it gave, recorded to be given again on every load."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = build()
    return model, list(caught)
