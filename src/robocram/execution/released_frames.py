"""Letting go of what a kept failure's frames hold.

A task keeps its failure for the task tree, and a failure's traceback keeps every frame it
passed through with their locals: collision scenes, planner snapshots, costmaps. A long
activity recovers from hundreds of failures; kept whole, they held every failed motion's
collision scene (native memory: a drafted Stretch's clearing grew past 20 GB). Only the
locals go: the traceback (files, lines, function names) and the failure's own fields stay,
so a failure prints and reads as before.
"""

from __future__ import annotations

import contextlib
import inspect

_SUSPENDABLE = inspect.CO_GENERATOR | inspect.CO_COROUTINE | inspect.CO_ASYNC_GENERATOR


def release_frames(error: BaseException) -> None:
    """Clear the locals of the finished frames that ``error`` passed through, and those of
    the failures it carries (its context, its cause, a plan failure's ``causes``).

    Running frames are left alone (Python refuses them), and so are generator and
    coroutine frames: clearing one would close its generator, which may still be asked
    for more.
    """
    seen: set[int] = set()
    todo = [error]
    while todo:
        failure = todo.pop()
        if id(failure) in seen:
            continue
        seen.add(id(failure))
        tb = failure.__traceback__
        while tb is not None:
            frame = tb.tb_frame
            if not frame.f_code.co_flags & _SUSPENDABLE:
                with contextlib.suppress(RuntimeError):  # a running frame's are in use
                    frame.clear()
            tb = tb.tb_next
        todo.extend(e for e in (failure.__context__, failure.__cause__) if e is not None)
        causes = getattr(failure, "causes", None)
        if isinstance(causes, list | tuple):
            todo.extend(c for c in causes if isinstance(c, BaseException))
