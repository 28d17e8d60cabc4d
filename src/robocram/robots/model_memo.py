"""Parsed robot models shared by equal loads while something holds them.

What a plan learns about a robot's kinematics (IK solvers, start tables, reach bounds,
link radii) is kept on its :class:`~robocram.robots.RobotModel`, which lives as long as the
model. Models are immutable, so loads of the same file (same bytes, same package paths,
same added frames and boxes) share one; a changed file is parsed anew.

The memo holds its models weakly: it keeps no model alive of its own, so no process-wide
state outlives its users. A model lives while a world's robot, a description or a scene
holds it: a batch worker's world, kept across its variants, or a user's scene while the
next one is built, share it; once nothing holds it, the next load parses the file again
and starts with nothing kept. The process's memo is ``robocram.robots.robot_model.MODELS``.
"""

from __future__ import annotations

import hashlib
import threading
import warnings
import weakref
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Generic, TypeVar

from robocram.robots.model_additions import BoxSpec, FrameSpec, JointCoupling

M = TypeVar("M")  # the model type (RobotModel, which keeps the process's memo)

ModelKey = tuple[
    str,
    str,
    tuple[Path, ...],
    tuple[FrameSpec, ...],
    tuple[BoxSpec, ...],
    bool,
    tuple[JointCoupling, ...],
]


@dataclass(frozen=True)
class _Kept(Generic[M]):
    """A model held weakly, and the warnings its build gave (given again on each load)."""

    ref: weakref.ref[M]
    warned: tuple[warnings.WarningMessage, ...]


class ModelMemo(Generic[M]):
    """The models built and still held somewhere, by the content they were built from."""

    def __init__(self) -> None:
        self._models: dict[ModelKey, _Kept[M]] = {}
        self._lock = threading.Lock()  # a dying model's entry leaves from any thread

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
        """The live model of ``file``'s current bytes and these additions, or ``build()``.

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
        with self._lock:
            kept = self._models.get(key)
        found = kept.ref() if kept is not None else None
        if found is None or kept is None:
            model, warned = _built(build)
            kept = _Kept(weakref.ref(model, self._forget(key)), warned)
            with self._lock:
                self._models[key] = kept
        else:
            model = found
        for w in kept.warned:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, source=w.source)
        return model

    def _forget(self, key: ModelKey) -> Callable[[weakref.ref[M]], None]:
        """The callback dropping ``key``'s entry when its model dies (not a newer one's)."""

        def gone(ref: weakref.ref[M]) -> None:
            with self._lock:
                kept = self._models.get(key)
                if kept is not None and kept.ref is ref:
                    del self._models[key]

        return gone

    def __len__(self) -> int:
        """How many models are held somewhere (and so shared by the next equal load)."""
        with self._lock:
            return sum(1 for kept in self._models.values() if kept.ref() is not None)

    def clear(self) -> None:
        """Forget every model (they live on while something else holds them)."""
        with self._lock:
            self._models.clear()


def _built(build: Callable[[], M]) -> tuple[M, tuple[warnings.WarningMessage, ...]]:
    """``build()`` and the warnings it gave, recorded to be given again on every load."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = build()
    return model, tuple(caught)
