"""What the tool actions return: typed, frozen results (docs/tool_actions.md)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PouringResult:
    """A pour: ``amount`` [ml] from ``source`` into ``target``; in projection, of the
    ``particles`` standing for it, how many ``landed`` in the target and ``spilled``
    (None where nobody counts them); ``fraction`` of the tilt path reached."""

    source: str
    target: str
    amount: float
    fraction: float
    particles: int | None
    landed: int | None
    spilled: int | None

    @property
    def landed_share(self) -> float | None:
        """The share (0..1) of the particles that landed in the target."""
        if self.particles is None or self.landed is None or self.particles == 0:
            return None
        return self.landed / self.particles


@dataclass(frozen=True)
class WipingResult:
    """A wipe of a region of ``surface`` with ``tool``: the ``covered`` share (0..1) of the
    region the tool's underside passed over in contact, and the ``fraction`` of the
    coverage path reached."""

    surface: str
    tool: str
    covered: float
    fraction: float


@dataclass(frozen=True)
class CuttingResult:
    """A cut of ``object`` with ``tool``: the ``slices`` it became (names, along its
    axis; in projection) and their ``widths`` [m], and the ``fraction`` of the sawing path
    reached."""

    object: str
    tool: str
    slices: tuple[str, ...]
    widths: tuple[float, ...]
    fraction: float


@dataclass(frozen=True)
class MixingResult:
    """A stir of ``container``'s inside with ``tool``: ``turns`` of a spiral no wider than
    ``radius`` [m] (clear of the rim by ``clearance`` [m] at least, as planned), and the
    ``fraction`` of it reached."""

    container: str
    tool: str
    turns: float
    radius: float
    clearance: float
    fraction: float
