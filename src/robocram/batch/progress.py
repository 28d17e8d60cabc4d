"""A progress bar over a running batch: variants done, failed and lost, as they finish.

Shown on a terminal only: ``progress=None`` turns it on when the stream (standard output by
default) is a TTY, so logs, pipes and CI stay clean; ``True`` or ``False`` decide outright.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any, TextIO

from robocram.batch.result import VariantResult, VariantStatus

if TYPE_CHECKING:
    from tqdm import tqdm


class ProgressBar:
    """Counts finished variants on ``stream``; does nothing when it is off."""

    def __init__(self, total: int, progress: bool | None, stream: TextIO | None = None) -> None:
        out = sys.stdout if stream is None else stream
        on = _is_terminal(out) if progress is None else bool(progress)
        self.failed = 0
        self.lost = 0
        self._bar: tqdm[Any] | None = None
        if on:
            from tqdm import tqdm  # ~20 ms with importlib.metadata: only for a bar shown

            self._bar = tqdm(total=total, file=out, unit="variant", desc="batch", leave=True)

    @property
    def shown(self) -> bool:
        """Whether the bar is drawn."""
        return self._bar is not None

    def update(self, result: VariantResult) -> None:
        """Count one finished variant."""
        self.failed += result.status is VariantStatus.FAILED
        self.lost += result.status is VariantStatus.LOST
        if self._bar is not None:
            self._bar.set_postfix(failed=self.failed, lost=self.lost, refresh=False)
            self._bar.update(1)

    def close(self) -> None:
        """Finish the bar's line (idempotent)."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def _is_terminal(stream: TextIO) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):  # a closed or stream-like object without a TTY
        return False
