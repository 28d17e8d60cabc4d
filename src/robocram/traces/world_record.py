"""World states and scenes as the trace store keeps them, and back again.

A :class:`StoredWorldState` is what a motion leaves behind: every object's root pose, the
joint positions of articulated bodies and the attachments. A scene is the list of body
recipes (robots by description name and URDF digest, shapes, meshes, URDFs) from which a
replay rebuilds the world in a fresh physics client. Bodies a run adds after its start
(a pour's particles, a cut loaf's slices) are kept with each state as recipes too, and a
body of the scene a state lacks was removed: applying the state adds and removes them.
"""

from __future__ import annotations

import json
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field
from typing import Any

from sqlalchemy.orm import Session

from robocram.tf import Pose
from robocram.traces.body_files import found_file, stored_file
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import TraceError
from robocram.traces.robot_model_record import description_row, urdf_digest
from robocram.traces.robot_rebuild import add_traced_robot
from robocram.traces.schema import WorldStateRow
from robocram.world import Attachment, MeshSpec, RobotObject, ShapeSpec, UrdfSpec, World

BodyRecipe = dict[str, Any]  # JSON-ready: name, type, and robot, shape, mesh or URDF


@dataclass(frozen=True)
class StoredWorldState:
    """Object poses (map), joint positions and attachments of a world at one moment."""

    time: float  # [s] since the epoch
    sim_time: float  # [s] simulated
    poses: dict[str, Pose]
    joints: dict[str, dict[str, float]]  # object -> joint -> [rad] or [m]
    attachments: tuple[Attachment, ...]
    added: dict[str, BodyRecipe] = field(default_factory=dict)  # name -> body recipe

    @classmethod
    def capture(
        cls, world: World, time: float, scene: Collection[str] | None = None
    ) -> StoredWorldState:
        """Read the state of ``world`` now; ``time`` [s since the epoch] stamps it.

        ``scene``: the names of the run's scene; the recipe of every other body is kept
        (None: none kept, the world is taken to hold the scene's bodies only).
        """
        objects = world.objects()
        attached = (world.bodies.attached_to(obj) for obj in objects)
        added = (
            {}
            if scene is None
            else {o.name: body_recipe(o) for o in objects if o.name not in scene}
        )
        return cls(
            time=time,
            sim_time=world.physics.time,
            poses={obj.name: world.pose(obj) for obj in objects},
            joints={obj.name: js for obj in objects if (js := world.joint_states(obj))},
            attachments=tuple(a for a in attached if a is not None),
            added=added,
        )

    def apply(self, world: World, scene: str | None = None) -> None:
        """Put ``world`` (built from the run's scene) into this state: the bodies the state
        adds are made from their recipes, those it lacks are removed, and ``scene`` (the
        run's scene, JSON) brings back a body of it removed earlier (a replay going back).

        Raises:
            TraceError: the state names a body neither the world, its recipes nor
                ``scene`` has (apply it to the world of the run's scene).
        """
        self._add_and_remove(world, scene)
        for obj in world.objects():
            if world.bodies.attached_to(obj) is not None:
                world.detach(obj)
        for name, pose in self.poses.items():
            world.set_pose(name, pose)
        for name, joints in self.joints.items():
            _set_joints(world, name, joints)
        for att in self.attachments:
            world.attach(att.obj, att.robot, att.link)

    def _add_and_remove(self, world: World, scene: str | None) -> None:
        present = {obj.name for obj in world.objects()}
        recipes = dict(self.added)
        if scene is not None:
            recipes |= {r["name"]: r for r in json.loads(scene) if r["name"] not in recipes}
        missing = sorted(set(self.poses) - present - set(recipes))
        if missing:
            raise TraceError(f"the world has no objects {missing}; replay into the run's scene")
        for name in sorted(set(self.poses) - present):
            add_body(world, recipes[name])
        for obj in world.objects():
            if obj.name not in self.poses:  # removed by the run (a loaf cut into slices)
                world.remove(obj)


def _set_joints(world: World, name: str, joints: dict[str, float]) -> None:
    """Set masters first, then mimic followers alone, so both keep their stored values."""
    handle = world.object(name)
    model = handle.description.model if isinstance(handle, RobotObject) else None
    followers = {
        j for j in joints if model is not None and j in model.joints and model.joints[j].mimic
    }
    world.set_joint_states(name, {j: v for j, v in joints.items() if j not in followers})
    if followers:
        world.set_joint_states(name, {j: joints[j] for j in followers})


def state_row(run_id: int, task_id: int | None, state: StoredWorldState) -> dict[str, Any]:
    """The ``world_states`` row of ``state`` (Core executemany on the tracer's hot path)."""
    attachments = [[a.obj, a.robot, a.link, _pose_list(a.link_T_obj)] for a in state.attachments]
    return {
        "run_id": run_id,
        "task_id": task_id,
        "time": state.time,
        "sim_time": state.sim_time,
        "poses": json.dumps({n: _pose_list(p) for n, p in state.poses.items()}),
        "joints": json.dumps(state.joints),
        "attachments": json.dumps(attachments),
        "added": json.dumps(state.added) if state.added else None,
    }


def load_world_state(session: Session, state_id: int) -> StoredWorldState:
    """Read the stored state ``state_id``."""
    row = session.get_one(WorldStateRow, state_id)
    attachments = json.loads(row.attachments)
    return StoredWorldState(
        time=row.time,
        sim_time=row.sim_time,
        poses={n: _pose_of(p) for n, p in json.loads(row.poses).items()},
        joints=json.loads(row.joints),
        attachments=tuple(Attachment(o, r, link, _pose_of(p)) for o, r, link, p in attachments),
        added=json.loads(row.added) if row.added else {},
    )


def _pose_list(pose: Pose) -> list[float]:
    return [*pose.position, *pose.orientation]


def _pose_of(values: list[float]) -> Pose:
    x, y, z, qx, qy, qz, qw = values
    return Pose((x, y, z), (qx, qy, qz, qw))


def scene_of(world: World) -> str:
    """The recipes of the world's bodies as JSON text, in insertion order."""
    return json.dumps([body_recipe(obj) for obj in world.objects()])


def scene_names(scene: str) -> frozenset[str]:
    """The names of the bodies of a stored scene (JSON from :func:`scene_of`)."""
    return frozenset(recipe["name"] for recipe in json.loads(scene))


def body_recipe(obj: Any) -> BodyRecipe:
    """What rebuilds ``obj`` in another world: its name, type and robot or shape, mesh or
    URDF (JSON-ready)."""
    recipe: BodyRecipe = {"name": obj.name, "type": obj.type}
    spec = obj.spec
    if isinstance(obj, RobotObject):
        recipe["robot"] = obj.description.name
        recipe["urdf_digest"] = urdf_digest(obj.description.model)  # robot_models key
        if obj.description.source:  # a description file or module: the name is not enough
            recipe["source"] = obj.description.source
            recipe["description_digest"] = description_row(obj.description)["digest"]
    elif isinstance(spec, ShapeSpec):
        recipe["shape"] = {"shape": spec.shape, "size": spec.size, "mass": spec.mass}
        recipe["shape"]["color"] = spec.color
    elif isinstance(spec, MeshSpec):
        recipe["mesh"] = stored_file(spec.path) | {"scale": spec.scale, "mass": spec.mass}
        recipe["mesh"]["color"] = spec.color
    elif isinstance(spec, UrdfSpec):
        recipe["urdf"] = stored_file(spec.path) | {"fixed_base": spec.fixed_base}
        recipe["urdf"] |= {"scale": spec.scale, "mass": spec.mass}
    return recipe


def build_scene(
    scene: str,
    world: World | None = None,
    robots: Mapping[str, str] | None = None,
    db: TraceDatabase | None = None,
) -> World:
    """Re-create the bodies of a stored scene (JSON from :func:`scene_of`) in a world.

    A robot described by a file is built from ``robots[description name]`` if given, else
    from the file it ran with, else from ``db``'s copy of it (see
    :mod:`robocram.traces.robot_rebuild`).

    Raises:
        RobotNotRebuilt: a robot's description file is given but fails to load or
            describes another URDF than the one that ran; or, with no copy in ``db``, the
            file it ran with is missing, fails or changed.
    """
    world = world if world is not None else World()
    for recipe in json.loads(scene):
        add_body(world, recipe, robots, db)
    return world


def add_body(
    world: World,
    recipe: BodyRecipe,
    robots: Mapping[str, str] | None = None,
    db: TraceDatabase | None = None,
) -> None:
    """Add the body of ``recipe`` (from :func:`body_recipe`) to ``world``."""
    name, kind = recipe["name"], recipe["type"]
    if "robot" in recipe:
        add_traced_robot(world, recipe, dict(robots or {}), db)
    elif "shape" in recipe:
        s = recipe["shape"]
        spec = ShapeSpec(s["shape"], tuple(s["size"]), s["mass"], tuple(s["color"]))
        world.add_object(name, kind, spec)
    elif "mesh" in recipe:
        m = recipe["mesh"]
        world.add_object(
            name, kind, MeshSpec(found_file(name, m), m["scale"], m["mass"], tuple(m["color"]))
        )
    elif "urdf" in recipe:
        u = recipe["urdf"]
        urdf = UrdfSpec(found_file(name, u), u["fixed_base"], u["scale"], u["mass"])
        world.add_object(name, kind, urdf)
