"""Robot drafts, each URDF drafted once per test process.

Several modules draft the same robot: ARMAR-6 in six, Centauro, the DoNBot and the
Stretch in three, the Fetch, the UR5, Kevin, the MABI, the Z1, the SO-101 and TALOS in
two each, at 0.3-1.5 s of CPU a draft. A draft is a value (a frozen description with its
reasons and doubts), the same on every call, so one per process serves them all. It is
drafted quietly (its doubts and missing meshes): a test that judges those warnings
drafts for itself.
"""

from __future__ import annotations

import functools
import warnings
from pathlib import Path

from robocram.robots import DraftDescription, draft_description


def drafted(urdf: Path) -> DraftDescription:
    """``draft_description(urdf)``, drafted once per process, without its warnings."""
    return _drafted(urdf.resolve())


@functools.cache
def _drafted(urdf: Path) -> DraftDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return draft_description(urdf)


def drafted_module(urdf: Path, module: Path) -> Path:
    """``module`` written with the draft of ``urdf`` (:func:`drafted`) as its source."""
    module.write_text(drafted(urdf).source(module), "utf-8")
    return module
