"""The worker side of batch projection: one world per robot, restored between variants.

A worker builds each robot's scene the first time a variant asks for it and captures its
state; every variant starts from that state, so a variant's result depends only on the
variant, never on which worker ran it or what that worker ran before.
"""

from __future__ import annotations

import gc
import os
import random
import signal
import socket
import time
from collections.abc import Callable
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, replace
from multiprocessing.connection import Connection
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol, TypeVar

import numpy as np

from robocram.batch.errors import BadVariant
from robocram.batch.object_placement import place_objects
from robocram.batch.plan_choices import choices_of
from robocram.batch.result import VariantResult, VariantStatus
from robocram.batch.variant import Variant
from robocram.projection import simulated_robot
from robocram.tf import PoseStamped
from robocram.world import World

if TYPE_CHECKING:
    from robocram.traces import Tracer


class Scene(Protocol):
    """What a scene factory returns (e.g. :class:`robocram.scenes.TabletopScene`)."""

    @property
    def world(self) -> World: ...

    @property
    def robot(self) -> str: ...

    @property
    def look_target(self) -> PoseStamped: ...


T = TypeVar("T")
# What a plan may raise that ends its variant, not its worker: a plan calling sys.exit()
# or raising KeyboardInterrupt itself (a worker ignores Ctrl-C: the parent handles it)
PLAN_EXITS = (Exception, SystemExit, KeyboardInterrupt)
SceneFactory = Callable[[str], Scene]
Plan = Callable[..., Any]  # plan(look_target, **parameters), run inside simulated_robot


@dataclass(frozen=True)
class WorkerConfig:
    """What every worker of one batch shares (pickled to each spawned process)."""

    plan: Plan
    scene: SceneFactory
    robot: str
    traces: Path | None = None


class VariantRunner:
    """Runs variants in worlds it builds once per robot and restores before each variant."""

    def __init__(self, config: WorkerConfig) -> None:
        self.config = config
        self._scenes: dict[str, Scene] = {}

    def _scene(self, robot: str) -> Scene:
        if robot not in self._scenes:
            self._scenes[robot] = self.config.scene(robot)
        return self._scenes[robot]

    def run(self, index: int, variant: Variant) -> VariantResult:
        """Run one variant from its robot's initial world; exceptions become the result.

        The result's ``split`` says where its time went: building the scene (a worker's
        first variant), restoring the world, placing objects, the tracer, the simulated
        robot's set-up and the plan itself.
        """
        clock = _SplitClock()
        runs: list[int] = []  # the tracer's run ids, filled as the run starts
        try:
            scene = clock.after("scene", self._scene(variant.robot or self.config.robot))
            with (
                scene.world.snapshots.stored_state()
            ):  # the next variant starts from the scene as built
                clock.mark("restore")
                look_target = clock.after("place", _place_objects(scene, variant))
                _seed_everything(variant.seed)
                with self._tracing(scene.world) as tracer:
                    runs = tracer.runs if tracer is not None else runs
                    clock.mark("trace")
                    with simulated_robot(scene.world, scene.robot):
                        clock.mark("robot")
                        chosen = self.config.plan(look_target, **variant.parameter_dict())
                        clock.mark("plan")
                    clock.mark("robot")
                clock.mark("trace")
            clock.mark("restore")
        except PLAN_EXITS as err:  # a variant's failure is data, the batch goes on
            return VariantResult(
                index, variant.name, VariantStatus.FAILED, type(err).__name__,
                error_text(err), clock.total(), run_id=runs[-1] if runs else None,
                split=clock.split(),
            )  # fmt: skip
        return _success(index, variant, chosen, clock, runs)

    def _tracing(self, world: World) -> AbstractContextManager[Tracer | None]:
        if self.config.traces is None:
            return nullcontext(None)
        from robocram.traces import trace_to  # SQLAlchemy: loaded by a batch that traces

        return trace_to(self.config.traces, world=world)


def error_text(err: BaseException) -> str:
    """``str(err)``, or a stand-in naming its type when turning it into text fails."""
    try:
        return str(err)
    except Exception as failed:  # the plan's error is still reported, and the worker kept
        return f"<{type(err).__name__} that cannot be shown: {type(failed).__name__}>"


def _place_objects(scene: Scene, variant: Variant) -> PoseStamped:
    """Move (and jitter) the variant's objects; return where the plan should look."""
    world = scene.world
    place_objects(
        world, variant.name, variant.object_shifts, variant.object_poses, variant.jitter,
        variant.seed,
    )  # fmt: skip
    if variant.look_at is None:
        return scene.look_target
    if variant.look_at not in world:
        raise BadVariant("look_at", variant.look_at, f"variant {variant.name!r}: not in the scene")
    return PoseStamped("map", world.pose(variant.look_at).position)


def _seed_everything(seed: int) -> None:
    """Seed the global generators a plan might use, so reruns match."""
    random.seed(seed)
    np.random.seed(seed)


class _SplitClock:
    """Wall time [s] spent per phase of a variant, added up as marks are passed."""

    def __init__(self) -> None:
        self.start = self.last = time.perf_counter()
        self.spent: dict[str, float] = {}

    def mark(self, phase: str) -> None:
        """The time since the last mark was spent in ``phase``."""
        now = time.perf_counter()
        self.spent[phase] = self.spent.get(phase, 0.0) + now - self.last
        self.last = now

    def after(self, phase: str, value: T) -> T:
        """``value``, computed in ``phase`` (mark it, pass the value through)."""
        self.mark(phase)
        return value

    def total(self) -> float:
        return time.perf_counter() - self.start

    def split(self) -> tuple[tuple[str, float], ...]:
        return tuple(self.spent.items())


def _success(
    index: int, variant: Variant, chosen: object, clock: _SplitClock, runs: list[int]
) -> VariantResult:
    picked = choices_of(chosen)
    return VariantResult(
        index, variant.name, VariantStatus.SUCCEEDED, duration=clock.total(),
        split=clock.split(),
        arm=picked.arm, grasp=picked.grasp, grasp_frame=picked.grasp_frame,
        grasp_name=picked.grasp_name, locations=picked.locations,
        run_id=runs[-1] if runs else None,
    )  # fmt: skip


def worker_main(config: WorkerConfig, conn: Connection) -> None:
    """Entry point of a spawned worker: answer each ``(index, variant)`` until ``None``."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    runner = VariantRunner(config)
    host = socket.gethostname()
    kept = False
    try:
        while True:
            try:
                job = conn.recv()
            except EOFError:  # the parent went away
                return
            if job is None:
                return
            index, variant = job
            conn.send(replace(runner.run(index, variant), worker=os.getpid(), node=host))
            if not kept:
                _keep_built()
                kept = True
    finally:
        gc.unfreeze()  # collected at exit as usual (bindings count what outlives them)


def _keep_built() -> None:
    """Take what the first variant built and the worker keeps (its scene, IK tables,
    reachability maps: some 100,000 objects) out of the collector's sight.

    The collector's full passes walk every tracked object; in a worker they found nothing
    to free in what it keeps and cost 3-4 ms of a 110 ms variant. Only a worker process
    does this: the interpreter is the worker's own.
    """
    gc.collect()
    gc.freeze()
