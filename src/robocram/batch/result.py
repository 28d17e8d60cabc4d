"""What one variant did: its status, the failure if any, the time it took, what it chose."""

from __future__ import annotations

import enum
from dataclasses import dataclass, replace

Pose7 = tuple[float, float, float, float, float, float, float]  # x, y, z [m], qx, qy, qz, qw


class VariantStatus(enum.Enum):
    """How a variant ended."""

    SUCCEEDED = "succeeded"
    FAILED = "failed"  # the plan raised: a plan failure or any other exception
    LOST = "lost"  # its worker died (killed, crashed, its node lost) before it answered


@dataclass(frozen=True)
class VariantResult:
    """One variant's outcome; ``duration`` is the only field that depends on the machine."""

    index: int  # position of the variant in the batch
    name: str
    status: VariantStatus
    failure_type: str | None = None  # class name of the exception, or of the lost cause
    message: str = ""
    duration: float = 0.0  # [s] wall time of the plan in its worker
    arm: str | None = None  # what the plan chose (None when it did not get that far)
    grasp: Pose7 | None = None  # the grasp pose it reached, in its frame
    grasp_frame: str | None = None
    grasp_name: str | None = None  # the grasp model's name of it: "top", "front", "rim", ...
    locations: tuple[tuple[str, Pose7], ...] = ()  # (what for, map pose): stands, spots
    worker: int = -1  # process id of the worker that ran it
    node: str = ""  # where that worker ran: the host name, or the Ray node id
    run_id: int | None = None  # its run in the trace store, when one was given
    rerun: bool = False  # run a second time, its first worker's node having been lost
    split: tuple[tuple[str, float], ...] = ()  # [s] per phase: scene, restore, plan, ...

    @property
    def succeeded(self) -> bool:
        """Whether the plan ran to its end."""
        return self.status is VariantStatus.SUCCEEDED

    def outcome(self) -> VariantResult:
        """This result without what depends on the machine (duration, worker, node, run id,
        whether a lost node made it run again, the split of its time)."""
        return replace(self, duration=0.0, worker=-1, node="", run_id=None, rerun=False, split=())
