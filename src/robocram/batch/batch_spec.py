"""A batch spec: the scene, robot and plan, and the variants, in a small YAML or JSON file.

The variants are either listed (each one a :meth:`Variant.from_mapping` entry) or drawn:
``variants: N`` with ``place`` giving, per object, a number or a ``[low, high]`` range per
axis (``x``, ``y``, ``z`` [m], ``yaw`` [rad]), sampled uniformly from ``seed``. Placements
shift the object from the scene's pose, or put it at an absolute pose in ``map`` with
``frame: map`` (then ``x``, ``y`` and ``z`` are required). See examples/batch_tabletop.yaml
and examples/batch_kitchen.yaml.
"""

from __future__ import annotations

import importlib
import json
import math
import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from robocram.batch.breakfast_activity import breakfast
from robocram.batch.drawn_variants import Axis, DrawnVariants
from robocram.batch.errors import BadSpec, BatchError
from robocram.batch.kitchen_transport import transport_item
from robocram.batch.variant import MAX_SEED, Variant  # a variant's seed is `seed + index`
from robocram.batch.worker import Plan, SceneFactory
from robocram.plans import pick_up
from robocram.robots import DescriptionError
from robocram.robots.description_source import description_from
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.scenes.breakfast_scene import breakfast_scene

SPEC_KEYS = (
    "scene", "robot", "plan", "seed", "variants", "place", "look_at", "parameters", "jitter",
    "workers", "backend", "max_variants",
)  # fmt: skip
MAX_VARIANTS = 100_000  # a spec asks for more with `max_variants:` (docs/batch.md)
PLACE_KEYS = ("frame", "x", "y", "z", "yaw")
FRAMES = ("scene", "map")  # shift from the scene's pose, or an absolute pose
SCENES: dict[str, SceneFactory] = {
    "tabletop": tabletop_scene, "kitchen": kitchen_scene, "breakfast": breakfast_scene,
}  # fmt: skip
PLANS: dict[str, Plan] = {"pick_up": pick_up, "transport": transport_item, "breakfast": breakfast}


@dataclass(frozen=True)
class BatchSpec:
    """A read spec: what :func:`~robocram.batch.project_variants` needs."""

    scene: SceneFactory
    robot: str
    plan: Plan
    variants: Sequence[Variant]  # listed: a tuple; drawn: DrawnVariants, drawn as they run
    workers: int | None = None  # None: the command line's choice
    backend: str | None = None


def load_spec(path: str | Path) -> BatchSpec:
    """Read a ``.yaml``/``.yml``/``.json`` spec; :class:`BadSpec` names any bad key."""
    path = Path(path)
    data = _read(path)
    if not isinstance(data, Mapping):
        raise BadSpec(path, "(top level)", data, f"give a mapping with keys {', '.join(SPEC_KEYS)}")
    for key in data:
        if key not in SPEC_KEYS:
            raise BadSpec(path, str(key), data[key], f"not a spec key; use {', '.join(SPEC_KEYS)}")
    if str(path.resolve().parent) not in sys.path:  # plans and scenes next to the spec
        sys.path.insert(0, str(path.resolve().parent))
    try:
        return BatchSpec(
            _named(path, "scene", data.get("scene", "tabletop"), SCENES),
            _robot(path, data.get("robot", "pr2")),
            _named(path, "plan", data.get("plan", "pick_up"), PLANS),
            _variants(path, data),
            _optional_int(path, "workers", data.get("workers")),
            _optional_string(path, "backend", data.get("backend")),
        )
    except BadSpec:
        raise
    except BatchError as err:  # a variant's own check: name where it came from
        raise BadSpec(path, "variants", "...", str(err)) from err


def _read(path: Path) -> object:
    if path.suffix not in (".yaml", ".yml", ".json"):
        raise BadSpec(path, "(file)", path.suffix, "give a .yaml, .yml or .json spec")
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as err:
        raise BadSpec(path, "(file)", str(path), f"cannot read it ({err.strerror})") from err
    except UnicodeDecodeError as err:
        raise BadSpec(
            path,
            "(file)",
            path.name,
            f"not UTF-8 text (byte {err.object[err.start]:#04x} at offset {err.start}); "
            "a spec is a YAML or JSON text file saved as UTF-8",
        ) from err
    try:
        return json.loads(text) if path.suffix == ".json" else yaml.safe_load(text)
    except (json.JSONDecodeError, yaml.YAMLError) as err:
        raise BadSpec(path, "(file)", path.name, f"not valid {path.suffix[1:]}: {err}") from err


def _string(path: Path, key: str, value: object) -> str:
    if not (isinstance(value, str) and value):
        raise BadSpec(path, key, value, "give a name")
    return value


def _robot(path: Path, value: object) -> str:
    """A built-in robot's name, ``pkg.mod:NAME``, or a description file (relative: to the
    spec), checked now: a missing file, a folder, a URDF or a file that defines no
    description would otherwise fail in every worker."""
    spec = _string(path, "robot", value)
    where, colon, name = spec.partition(":")
    if where.endswith(".py") and not Path(where).is_absolute():
        spec = f"{path.resolve().parent / where}{colon}{name}"
    if Path(where).suffix.lower() in (".urdf", ".xacro"):
        raise BadSpec(
            path, "robot", value, "a URDF is no robot description; draft one with "
            "`robocram robot draft URDF -o robot.py` and name robot.py",
        )  # fmt: skip
    try:
        description_from(spec)
    except DescriptionError as err:
        raise BadSpec(path, "robot", value, str(err)) from err
    except Exception as err:  # the user's file itself fails to run
        raise BadSpec(path, "robot", value, f"{spec} fails: {type(err).__name__}: {err}") from err
    return spec


def _optional_string(path: Path, key: str, value: object) -> str | None:
    return None if value is None else _string(path, key, value)


def _optional_int(path: Path, key: str, value: object) -> int | None:
    if value is None:
        return None
    if not isinstance(value, int) or isinstance(value, bool) or value < 1:
        raise BadSpec(path, key, value, "give a positive integer")
    return value


def _named(path: Path, key: str, value: object, known: Mapping[str, Callable[..., Any]]) -> Any:
    """A built-in by name, or ``module:function`` imported."""
    name = _string(path, key, value)
    if name in known:
        return known[name]
    fix = f"use {', '.join(sorted(known))} or module:function"
    module, _, attr = name.partition(":")
    if not attr:
        raise BadSpec(path, key, name, fix)
    try:
        found = getattr(importlib.import_module(module), attr)
    except (ImportError, AttributeError) as err:
        raise BadSpec(path, key, name, f"cannot import it ({err}); {fix}") from err
    if not callable(found):
        raise BadSpec(path, key, name, f"not a function; {fix}")
    return found


def _variants(path: Path, data: Mapping[str, Any]) -> Sequence[Variant]:
    given = data.get("variants")
    bound = data.get("max_variants", MAX_VARIANTS)
    if not isinstance(bound, int) or isinstance(bound, bool) or bound < 1:
        raise BadSpec(path, "max_variants", bound, "give a positive count")
    count = len(given) if isinstance(given, list) else given
    if isinstance(count, int) and not isinstance(count, bool) and count > bound:
        raise BadSpec(
            path, "variants", count,
            f"more than {bound} variants; raise the bound with `max_variants: {count}` "
            "if you mean it (each variant is a plan run)",
        )  # fmt: skip
    if isinstance(given, list):
        if "place" in data:
            raise BadSpec(path, "place", data["place"], "draws variants: give `variants: N`")
        return tuple(_listed(path, i, entry) for i, entry in enumerate(given))
    if not isinstance(given, int) or isinstance(given, bool) or given < 1:
        raise BadSpec(path, "variants", given, "give a count (with `place`) or a list")
    seed = data.get("seed", 0)
    if not isinstance(seed, int) or isinstance(seed, bool) or not 0 <= seed <= MAX_SEED:
        raise BadSpec(path, "seed", seed, f"give an integer in 0..{MAX_SEED} (2**32-1)")
    if seed + given - 1 > MAX_SEED:
        raise BadSpec(
            path, "seed", seed,
            f"variant i is seeded seed+i, and {seed}+{given - 1} passes {MAX_SEED}; "
            f"give a seed <= {MAX_SEED - given + 1}",
        )  # fmt: skip
    return _drawn(path, data, given, seed)


def _listed(path: Path, index: int, entry: object) -> Variant:
    try:
        return Variant.from_mapping(entry)  # type: ignore[arg-type]
    except BatchError as err:
        raise BadSpec(path, f"variants[{index}]", "...", str(err)) from err


def _drawn(path: Path, data: Mapping[str, Any], count: int, seed: int) -> DrawnVariants:
    place = data.get("place", {})
    if not isinstance(place, Mapping):
        raise BadSpec(path, "place", place, "give a mapping of object -> {x, y, z, yaw, frame}")
    ranges = {str(name): _ranges(path, str(name), axes) for name, axes in sorted(place.items())}
    common = {k: data[k] for k in ("look_at", "parameters", "jitter") if k in data}
    drawn = DrawnVariants(count, seed, ranges, common)
    drawn[0]  # the fields every variant shares are checked now, not in a worker
    return drawn


def _ranges(path: Path, name: str, axes: object) -> tuple[str, dict[str, Axis]]:
    key = f"place[{name!r}]"
    if not isinstance(axes, Mapping):
        raise BadSpec(path, key, axes, f"give a mapping with keys {', '.join(PLACE_KEYS)}")
    for axis in axes:
        if axis not in PLACE_KEYS:
            raise BadSpec(path, f"{key}.{axis}", axes[axis], f"use {', '.join(PLACE_KEYS)}")
    frame = axes.get("frame", "scene")
    if frame not in FRAMES:
        raise BadSpec(path, f"{key}.frame", frame, f"use {' or '.join(FRAMES)}")
    if frame == "map" and not {"x", "y", "z"} <= set(axes):
        raise BadSpec(path, key, dict(axes), "an absolute pose (frame: map) needs x, y and z")
    return frame, {a: _axis(path, f"{key}.{a}", v) for a, v in axes.items() if a != "frame"}


def _axis(path: Path, key: str, value: object) -> Axis:
    fix = "give a number or a [low, high] range (m, rad for yaw)"
    if isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value):
        return float(value)
    if not (isinstance(value, list | tuple) and len(value) == 2):
        raise BadSpec(path, key, value, fix)
    low, high = value
    numbers = all(isinstance(v, int | float) and not isinstance(v, bool) for v in value)
    if not (numbers and math.isfinite(low) and math.isfinite(high) and low <= high):
        raise BadSpec(path, key, value, fix + " with low <= high")
    return (float(low), float(high))
