"""Location designators resolved by costmaps: the generator the location resolver runs.

:class:`CostmapLocations` reads a designator's keys through the rules of
``location_keys.pl``, multiplies the cost layers they name into a :class:`Costmap`,
samples it lazily (seeded), turns each cell into a pose and shows it to the validators
the rules name. After ``max_rejections`` rejections in a row (CRAM's 30), or when the
costmap runs out before any pose was taken, it raises :class:`LocationNotFound`.
"""

from __future__ import annotations

import itertools
import math
from collections import Counter
from collections.abc import Iterator
from contextlib import nullcontext
from dataclasses import dataclass, field
from typing import Any, Literal, TypeVar

import numpy as np

from robocram.costmaps.cost_layer import CellRefiner, CostFunction, CostLayer, LocationQuery
from robocram.costmaps.cost_registry import BUILTIN_COST_FUNCTIONS, BUILTIN_VALIDATORS
from robocram.costmaps.costmap import Costmap
from robocram.costmaps.costmap_observers import notify_costmap
from robocram.costmaps.errors import CostmapInputError, LocationNotFound, LocationOutsideArea
from robocram.costmaps.grid import CostmapGrid
from robocram.costmaps.location_blame import Culprits
from robocram.costmaps.location_keys import LocationPlan, install_location_keys, plan_location
from robocram.costmaps.place_reach import held_objects
from robocram.costmaps.reach_reasoning import install_reach_predicates
from robocram.costmaps.reachability_map import ReachabilityMaps
from robocram.costmaps.validators import Validator, parked
from robocram.designators import LocationDesignator, LocationResolver
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import PlanningArea, RobotObject, World

Sampling = Literal["random", "best"]
_Function = TypeVar("_Function")
REFINE_CHUNK = 8  # cells whose lazy factors are computed together
ANCHOR_KEYS = ("at", "object", "target", "on", "in_", "near", "left_of", "right_of",
               "in_front_of", "behind")  # fmt: skip


@dataclass
class CostmapLocations:
    """Turns location designators into poses in ``world`` with costmaps and validators."""

    world: World
    seed: int = 0
    size: float = 4.0  # [m] side of the square searched around the designator's anchor
    resolution: float = 0.05  # [m]
    sampling: Sampling = "random"
    max_rejections: int = 30
    reach_maps: ReachabilityMaps = field(default_factory=ReachabilityMaps)
    cost_functions: dict[str, CostFunction] = field(
        default_factory=lambda: dict(BUILTIN_COST_FUNCTIONS)
    )
    validators: dict[str, Validator] = field(default_factory=lambda: dict(BUILTIN_VALIDATORS))

    def __post_init__(self) -> None:
        install_location_keys(self.world.kb)
        install_reach_predicates(self.world.kb, self.world)
        CostmapGrid.around((0.0, 0.0), self.size, self.resolution)  # checks both

    def add_cost_function(self, name: str, function: CostFunction) -> None:
        """Register the Python side of a ``location_cost(Key, name)`` rule."""
        self.cost_functions[name] = function

    def add_validator(self, name: str, function: Validator) -> None:
        """Register the Python side of a ``location_validator(Key, name)`` rule."""
        self.validators[name] = function

    def resolver(self, base: LocationResolver | None = None) -> LocationResolver:
        """``base`` (default: pose properties only) that also runs this generator."""
        return (base or LocationResolver()).with_generator("costmap", self.poses, priority=1)

    def plan(self, designator: object) -> LocationPlan:
        """The layers and validators the rules give ``designator``."""
        return plan_location(self.world.kb, designator)

    def query(self, designator: Any, plan: LocationPlan | None = None) -> LocationQuery:
        """The grid and robot the designator's costmap is built for."""
        plan = plan or self.plan(designator)
        robot = self._robot(designator, plan)
        designator = _with_holding_arm(self.world, designator, plan, robot)
        resolution = designator.get("resolution", self.resolution)
        size = designator.get("size", self.size)
        probe = LocationQuery(self.world, designator, CostmapGrid((0, 0), 1.0, (1, 1)), robot)
        centre = _anchor(probe, plan)
        _refuse_far_anchor(self.world, designator, centre, robot)
        grid = CostmapGrid.around(centre[:2], size, resolution)
        return LocationQuery(self.world, designator, grid, robot, self.reach_maps)

    def costmap(self, designator: object) -> Costmap:
        """The normalised product of the layers the designator's keys name."""
        query = self.query(designator)
        return self._costmap(query, self.plan(designator), lazy=False).costmap

    def poses(self, designator: object) -> Iterator[Pose]:
        """Accepted poses for ``designator``, lazily; nothing if no key asks for a costmap."""
        plan = self.plan(designator)
        if plan.empty:
            return
        query = self.query(designator, plan)
        layers = self._costmap(query, plan, lazy=True)
        notify_costmap(designator, layers.costmap)  # traces and viewers show it
        validators = [(name, self._validator(name)) for name in plan.validators]
        rejected: Counter[str] = Counter()
        accepted = in_a_row = 0
        for pose in self._stands_or_candidates(query, plan, layers):
            with parked(self.world, query.robot) if query.robot else nullcontext():
                culprit = next((n for n, check in validators if not check(query, pose)), None)
            if culprit is None:
                accepted, in_a_row = accepted + 1, 0
                yield pose
                continue
            rejected[culprit] += 1
            in_a_row += 1
            if in_a_row >= self.max_rejections:
                culprits = _culprits(query)
                raise LocationNotFound(designator, rejected, accepted, in_a_row, (), culprits)
        if accepted == 0:
            emptied_by, culprits = layers.emptied_by(), _culprits(query)
            area = query.grid.shape[0] * query.grid.resolution
            raise LocationNotFound(
                designator, rejected, accepted, in_a_row, emptied_by, culprits, area
            )

    def _stands_or_candidates(
        self, query: LocationQuery, plan: LocationPlan, layers: _Layers
    ) -> Iterator[Pose]:
        """The costmap's candidates; for a stand of a robot whose base is fixed, only where
        it stands: it cannot go anywhere else, and its validators still judge that one."""
        robot = query.robot
        if robot is not None and plan.robot_key is not None and robot.description.drive == "fixed":
            yield self.world.pose(robot)
            return
        yield from self._candidates(query, layers)

    def _robot(self, designator: Any, plan: LocationPlan) -> RobotObject | None:
        if plan.robot_key is None:
            robots = self.world.robots()
            return robots[0] if robots else None
        name = designator.get(plan.robot_key)
        if name not in self.world or not isinstance(self.world.object(name), RobotObject):
            known = ", ".join(r.name for r in self.world.robots()) or "none"
            raise CostmapInputError(
                f"{designator.description}: {plan.robot_key}={name!r} is not a robot in the "
                f"world (robots: {known}); add it with world.add_robot or fix the name",
                name,
            )
        return self.world.robot(name)

    def _validator(self, name: str) -> Validator:
        return _registered(self.validators, name, "location_validator", "add_validator")

    def _costmap(self, query: LocationQuery, plan: LocationPlan, lazy: bool) -> _Layers:
        alive = np.ones(query.grid.shape, dtype=bool)
        weights, refiners, heights, yaws = [], [], None, None
        zeroed_by: str | None = None
        refined_by: list[str] = []
        for key, name in plan.cost_functions:
            function = _registered(self.cost_functions, name, "location_cost", "add_cost_function")
            layer: CostLayer = function(query, query.designator.get(key), alive)
            weights.append(np.where(alive, layer.weights, 0.0))
            if layer.refine is not None and lazy:
                refiners.append(layer.refine)
                refined_by.append(name)
            elif layer.refine is not None:
                cells = np.argwhere(weights[-1] > 0)
                weights[-1][cells[:, 0], cells[:, 1]] *= layer.refine(cells)
            was_alive, alive = alive.any(), alive & (weights[-1] > 0)
            if was_alive and not alive.any():
                zeroed_by = name  # later layers only see zeros: this one is the cause
            heights = layer.heights if layer.heights is not None else heights
            yaws = layer.yaws if layer.yaws is not None else yaws
        if heights is None and query.robot is not None and query.designator.get("for_") is None:
            heights = _standing_heights(query)
        costmap = Costmap.from_layers(query.grid, weights, heights)
        return _Layers(costmap, yaws, refiners, plan, zeroed_by, tuple(refined_by))

    def _cells(self, layers: _Layers, rng: np.random.Generator) -> Iterator[tuple[int, int]]:
        """Cells drawn from the costmap, thinned by the lazy factors (rejection sampling)."""
        costmap = layers.costmap
        drawn = costmap.best_first() if self.sampling == "best" else costmap.weighted_random(rng)
        while chunk := list(itertools.islice(drawn, REFINE_CHUNK)):
            factors = np.ones(len(chunk))
            for refine in layers.refiners:
                factors *= refine(np.array(chunk, dtype=np.int64))
            for cell, factor in zip(chunk, factors, strict=True):
                keep = factor > 0 if self.sampling == "best" else rng.random() < factor
                if keep:
                    yield cell

    def _candidates(self, query: LocationQuery, layers: _Layers) -> Iterator[Pose]:
        rng = np.random.default_rng(query.designator.get("seed", self.seed))
        facing = _facing_point(query, layers.plan)
        placed = query.designator.get("for_")
        heading = self.world.pose(query.object(placed, "for_")).orientation if placed else None
        yaws = layers.yaws
        for cell in self._cells(layers, rng):
            x, y, z = layers.costmap.position(cell, rng if yaws is None else None)  # yaws: centres
            if heading is not None:
                yield Pose((x, y, z), heading)
                continue
            if yaws is not None:
                yaw = float(yaws[cell])
            elif facing is not None:
                yaw = math.atan2(facing[1] - y, facing[0] - x)
            else:
                yaw = 0.0
            yield Pose((x, y, z), quat.from_euler(0.0, 0.0, yaw))


@dataclass(frozen=True, eq=False)
class _Layers:
    """A costmap of the eager layers, the yaws, the lazy factors still to apply, the plan;
    the layer that zeroed every cell, and those whose lazy factors may zero the rest."""

    costmap: Costmap
    yaws: np.ndarray | None
    refiners: list[CellRefiner]
    plan: LocationPlan
    zeroed_by: str | None = None
    refined_by: tuple[str, ...] = ()

    def emptied_by(self) -> tuple[str, ...]:
        """The layers to blame when no candidate came: the one that zeroed the grid, else
        the lazy ones (their factors refused every cell drawn)."""
        return (self.zeroed_by,) if self.zeroed_by else self.refined_by


def _registered(registry: dict[str, _Function], name: str, rule: str, adder: str) -> _Function:
    """``registry[name]``, or an error saying the ``rule`` names a function nobody added."""
    found = registry.get(name)
    if found is None:
        raise CostmapInputError(
            f"a {rule} rule names {name!r}, which has no Python function; register one with "
            f"{adder}",
            name,
        )
    return found


def _with_holding_arm(
    world: World, designator: Any, plan: LocationPlan, robot: RobotObject | None
) -> Any:
    """A ``reachable_for`` target for a robot holding something in one hand is where that
    hand puts it down: the designator with ``arm`` set to it (unless it names an arm)."""
    if robot is None or plan.robot_key != "reachable_for" or designator.get("object") is not None:
        return designator
    if designator.get("arm") is not None or designator.get("target") is None:
        return designator
    arms = {arm for arm, _ in held_objects(world, robot)}
    if len(arms) != 1:
        return designator
    return LocationDesignator(*designator.properties, ("arm", arms.pop()))


def _culprits(query: LocationQuery) -> Culprits:
    """The objects the refused candidates failed on; the robot, what it holds and the object
    the designator is about left out, and environments (a kitchen's walls): moving them is
    no remedy."""
    designator, target = query.designator, "the location"
    spared = set()
    for key in ("object", "for_"):
        if designator.get(key) is not None:
            spared.add(query.object(designator.get(key), key).name)
    if query.robot is not None:
        spared |= {query.robot.name, *query.world.bodies.attachments(query.robot)}
    if designator.get("object") is not None:
        target = query.object(designator.get("object"), "object").name
    elif designator.get("target") is not None:
        x, y, z = query.point(designator.get("target"), "target")
        target = f"the target ({x:.2f}, {y:.2f}, {z:.2f})"
    elif designator.get("for_") is not None:
        target = query.object(designator.get("for_"), "for_").name
    fixed = [o.name for o in query.world.objects(type="environment")]
    return query.blame.culprits(target, spared, fixed)


def _anchor(query: LocationQuery, plan: LocationPlan) -> tuple[float, float, float]:
    """The point the search is centred on: the first of :data:`ANCHOR_KEYS` given, else the
    value of the first key that makes a layer (a user's own key)."""
    designator = query.designator
    keys = [*ANCHOR_KEYS, *(key for key, _ in plan.cost_functions if key not in ANCHOR_KEYS)]
    key = next((k for k in keys if designator.get(k) is not None and k != plan.robot_key), None)
    if key is None:
        raise CostmapInputError(
            f"{designator.description} says nothing to search around; give one of "
            f"{', '.join(ANCHOR_KEYS)}",
            designator,
        )
    return query.point(designator.get(key), key)


def _refuse_far_anchor(
    world: World, designator: Any, centre: tuple[float, float, float], robot: RobotObject | None
) -> None:
    """Refuse to search round a point outside the world's :class:`PlanningArea` (of its
    obstacles and the robot): a target 100 km away has no stand the robot can mean."""
    floors = [o.name for o in world.objects("floor")]
    here = [tuple(world.pose(robot).position[:2])] if robot is not None else []
    area = PlanningArea.of(world.contacts.obstacle_boxes(floors), here)  # type: ignore[arg-type]
    if area.contains(centre[0], centre[1]):
        return
    x, y, z = centre
    raise LocationOutsideArea(
        f"{designator.description}: its anchor ({x:.6g}, {y:.6g}, {z:.6g}) m is outside the "
        f"area plans search in: {area}; give a point near the world (in map)",
        centre,
        area,
    )


def _standing_heights(query: LocationQuery) -> np.ndarray:
    """A stand's height: where the robot's base stands now (the floor it is on). A legged
    robot's base, its trunk, stands 0.6 m over its feet; at 0 its legs would be in the
    floor and its arm 0.6 m too low at every stand checked."""
    robot = query.robot
    assert robot is not None
    return np.full(query.grid.shape, query.world.pose(robot).position[2])


def _facing_point(query: LocationQuery, plan: LocationPlan) -> tuple[float, float, float] | None:
    """Robots face the anchor; placed objects keep their heading (None)."""
    if query.robot is None or query.designator.get("for_") is not None:
        return None
    return _anchor(query, plan)
