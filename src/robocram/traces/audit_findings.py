"""What an audit of a run's trajectories finds: typed findings, and the report of a run.

Each :class:`AuditFinding` is one culprit (a pair of bodies, a joint) in one trajectory
(or at one stored world state), with its worst moment: how deep or how far over its bound
it went, and when. Samples of one trajectory with the same kind and culprit are one
finding; ``samples`` says how many samples showed it.
"""

from __future__ import annotations

import enum
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass


class FindingKind(enum.StrEnum):
    """What is wrong; the unit of a finding's ``amount`` and ``bound`` is the kind's."""

    WORLD_PENETRATION = "world-penetration"  # [m] depth
    ALLOWED_CONTACT_TOO_DEEP = "allowed-contact-too-deep"  # [m] depth
    SELF_PENETRATION = "self-penetration"  # [m] depth
    VELOCITY = "velocity"  # [rad/s | m/s]
    ACCELERATION = "acceleration"  # [rad/s^2 | m/s^2]
    JERK = "jerk"  # [rad/s^3 | m/s^3]
    VELOCITY_MISMATCH = "velocity-mismatch"  # stored against implied [rad/s | m/s]
    ACCELERATION_MISMATCH = "acceleration-mismatch"  # [rad/s^2 | m/s^2]
    TELEPORT = "teleport"  # [rad | m] jump without a trajectory

    @property
    def unit(self) -> str:
        """The unit its amounts are given in (``/s`` per derivative; rad for angles)."""
        return _UNITS[self]


_UNITS = {
    FindingKind.WORLD_PENETRATION: "m",
    FindingKind.ALLOWED_CONTACT_TOO_DEEP: "m",
    FindingKind.SELF_PENETRATION: "m",
    FindingKind.VELOCITY: "/s",
    FindingKind.ACCELERATION: "/s^2",
    FindingKind.JERK: "/s^3",
    FindingKind.VELOCITY_MISMATCH: "/s",
    FindingKind.ACCELERATION_MISMATCH: "/s^2",
    FindingKind.TELEPORT: "",
}
PENETRATIONS = (
    FindingKind.WORLD_PENETRATION,
    FindingKind.ALLOWED_CONTACT_TOO_DEEP,
    FindingKind.SELF_PENETRATION,
)


@dataclass(frozen=True)
class AuditFinding:
    """One culprit of one kind in one trajectory (``trajectory`` None: between them)."""

    run: int
    trajectory: int | None  # the stored trajectory's index in the run
    kind: FindingKind
    task_path: str | None  # the task the trajectory (or the stored state) belongs to
    time: float  # [s] from the run's start, on the replay clock: the worst moment
    what: str  # the culprit: "r_forearm_link / kitchen:table_top", "joint torso_lift_joint"
    amount: float  # penetration depth [m], the derivative's magnitude, or the jump
    bound: float  # what ``amount`` may be: the depth allowed, the limit, the tolerance
    samples: int = 1  # how many samples (or points) showed it

    @property
    def excess(self) -> float:
        """How far ``amount`` is over ``bound``."""
        return self.amount - self.bound

    def line(self) -> str:
        """One line: run, trajectory, kind, task, time, culprit, amount against its bound."""
        where = "-" if self.trajectory is None else str(self.trajectory)
        unit = self.kind.unit
        if self.kind in PENETRATIONS:
            size = f"{self.amount * 1e3:.2f} mm deep (allowed {self.bound * 1e3:.2f} mm)"
        elif self.kind is FindingKind.TELEPORT:
            size = f"jumped {self.amount:.4g} (tolerance {self.bound:.1g})"
        else:
            size = (
                f"{self.amount:.4g}{unit} (limit {self.bound:.4g}{unit}, over by {self.excess:.3g})"
            )
        return (
            f"run {self.run} traj {where} {self.kind.value} {self.task_path or '-'} "
            f"t={self.time:.3f}s {self.what}: {size} [{self.samples} samples]"
        )


@dataclass(frozen=True)
class FindingPlace:
    """Where findings are made: a run, a trajectory of it (or none) and its task."""

    run: int
    trajectory: int | None
    task_path: str | None
    start: float  # [s] from the run's start (replay clock) of the trajectory or state

    def finding(
        self, kind: FindingKind, t: float, what: str, amount: float, bound: float
    ) -> AuditFinding:
        """A finding here, ``t`` [s] after :attr:`start`."""
        return AuditFinding(
            self.run, self.trajectory, kind, self.task_path, self.start + t, what, amount, bound
        )


@dataclass(frozen=True)
class AuditReport:
    """The findings of one audit (of one run or many), and how much it looked at."""

    runs: tuple[int, ...]  # the runs audited
    findings: tuple[AuditFinding, ...]
    trajectories: int  # trajectories replayed
    configurations: int  # configurations checked for penetration
    not_audited: tuple[tuple[int, str], ...] = ()  # (run, why): no world stored to replay

    @property
    def clean(self) -> bool:
        """Whether nothing was found."""
        return not self.findings

    def counts(self) -> dict[FindingKind, int]:
        """Findings per kind, in the kinds' order."""
        counted = Counter(f.kind for f in self.findings)
        return {kind: counted[kind] for kind in FindingKind if counted[kind]}

    def worst(self, kind: FindingKind) -> AuditFinding | None:
        """The finding of ``kind`` furthest over its bound (None: none of that kind)."""
        found = [f for f in self.findings if f.kind is kind]
        return max(found, key=lambda f: f.excess) if found else None

    def of(self, kind: FindingKind) -> list[AuditFinding]:
        """The findings of ``kind``, in the order found."""
        return [f for f in self.findings if f.kind is kind]

    def summary_lines(self) -> list[str]:
        """What was audited, then per kind the count and the worst finding."""
        if self.runs:
            lines = [
                f"audited run(s) {', '.join(map(str, self.runs))}: {self.trajectories} "
                f"trajectories, {self.configurations} configurations checked; "
                + ("clean" if self.clean else f"{len(self.findings)} finding(s)")
            ]
        else:
            lines = ["audited no run"]
        for kind, count in self.counts().items():
            worst = max(self.of(kind), key=lambda f: f.excess)
            lines.append(f"  {kind.value:<24} {count:>4}  worst: {worst.what}, {_size(worst)}")
        lines += [f"  not audited: run {run}: {why}" for run, why in self.not_audited]
        return lines

    @classmethod
    def merged(cls, reports: Sequence[AuditReport]) -> AuditReport:
        """One report of several."""
        return cls(
            tuple(r for report in reports for r in report.runs),
            tuple(f for report in reports for f in report.findings),
            sum(r.trajectories for r in reports),
            sum(r.configurations for r in reports),
            tuple(n for report in reports for n in report.not_audited),
        )


def _size(finding: AuditFinding) -> str:
    if finding.kind in PENETRATIONS:
        return f"{finding.amount * 1e3:.2f} mm (bound {finding.bound * 1e3:.2f} mm)"
    return f"{finding.amount:.4g} (bound {finding.bound:.4g})"


def worst_per_culprit(findings: Iterable[AuditFinding]) -> list[AuditFinding]:
    """One finding per (run, trajectory, kind, culprit): the worst, counting the samples.

    Findings at stored states (no trajectory) are kept apart per state (task and time).
    """
    kept: dict[tuple[object, ...], AuditFinding] = {}
    for f in findings:
        key: tuple[object, ...] = (f.run, f.trajectory, f.kind, f.what)
        if f.trajectory is None:
            key += (f.task_path, f.time)
        old = kept.get(key)
        if old is None:
            kept[key] = f
            continue
        worst = f if f.excess > old.excess else old
        kept[key] = AuditFinding(
            worst.run, worst.trajectory, worst.kind, worst.task_path, worst.time, worst.what,
            worst.amount, worst.bound, old.samples + f.samples,
        )  # fmt: skip
    return list(kept.values())
