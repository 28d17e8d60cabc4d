"""A publisher that sends each message a fixed time after it was given, in order.

For tests: the driver's ``--tf-lag`` sends its transforms late, as a client's tf thread
sees them on a loaded machine (it handles the transforms published before a goal ended
after the goal's result), so the state after a goal can be checked not to depend on
how far the transforms lag.
"""

from __future__ import annotations

import threading
import time
from collections import deque

from robocram.ros_driver.goals import RosMessage


class LaggingPublisher:
    """Publishes through ``publisher`` ``lag`` seconds after each :meth:`publish`."""

    def __init__(self, publisher: RosMessage, lag: float) -> None:
        self.publisher = publisher
        self._lag = lag
        self._queue: deque[tuple[float, RosMessage]] = deque()
        self._ready = threading.Condition()
        threading.Thread(target=self._send, daemon=True).start()

    def publish(self, message: RosMessage) -> None:
        """Send ``message`` ``lag`` seconds from now, after those given before it."""
        with self._ready:
            self._queue.append((time.monotonic() + self._lag, message))
            self._ready.notify()

    def _send(self) -> None:
        while True:
            with self._ready:
                self._ready.wait_for(lambda: bool(self._queue))
                due, message = self._queue[0]
            time.sleep(max(0.0, due - time.monotonic()))
            with self._ready:
                self._queue.popleft()
            self.publisher.publish(message)
