"""Playing a replay: the viewer steps through its moments at the pace of the replay clock.

A background thread shows each moment after the replay time since the one before has passed
(scaled by ``speed``, each wait capped at :data:`MAX_PAUSE`), so trajectories play at their
own speed and the instants between motions do not stall. Moving the slider or pressing the
button again stops it.
"""

from __future__ import annotations

import threading
from collections.abc import Callable

from robocram.viewer.errors import ViewerArgumentError
from robocram.viewer.timeline import Timeline

MAX_PAUSE = 0.5  # [s] longest wait between two moments, however far apart they are
STOP_WAIT = 5.0  # [s] for the thread to notice a stop


class Player:
    """Shows ``timeline``'s moments one after another through ``show(index)``."""

    def __init__(self, timeline: Timeline, show: Callable[[int], None], speed: float = 1.0):
        if not speed > 0.0:
            raise ViewerArgumentError(f"the replay speed must be positive, got {speed}")
        self.timeline = timeline
        self.show = show
        self.speed = speed
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def pauses(self, start: int) -> list[tuple[int, float]]:
        """``(index, wait [s] before showing it)`` for every moment after ``start``."""
        steps = []
        for index in range(start + 1, len(self.timeline)):
            before, now = self.timeline[index - 1], self.timeline[index]
            gap = _replay_time(now.replay_time, now.time) - _replay_time(
                before.replay_time, before.time
            )
            steps.append((index, min(max(gap, 0.0) / self.speed, MAX_PAUSE)))
        return steps

    @property
    def playing(self) -> bool:
        """Whether the thread is stepping."""
        return self._thread is not None and self._thread.is_alive()

    def play(self, start: int) -> None:
        """Step from moment ``start`` to the last one, in a thread."""
        self.stop()
        self._stop.clear()
        steps = self.pauses(start)
        self._thread = threading.Thread(
            target=self._run, args=(steps,), name="robocram:replay-player", daemon=True
        )
        self._thread.start()

    def _run(self, steps: list[tuple[int, float]]) -> None:
        for index, pause in steps:
            if self._stop.wait(pause):
                return
            self.show(index)

    def stop(self) -> None:
        """Stop stepping (the moment on screen stays)."""
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(STOP_WAIT)
        self._thread = None

    def wait(self) -> None:
        """Wait until the last moment is shown (or the player is stopped)."""
        thread = self._thread
        if thread is not None:
            thread.join()


def _replay_time(replay_time: float | None, time: float) -> float:
    return replay_time if replay_time is not None else time
