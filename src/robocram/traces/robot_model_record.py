"""Robot models as the trace store keeps them: each URDF text once, named by its digest,
and the description of a robot read from a file, once per content.

A scene records a robot by its description's name, which is enough to rebuild the world
from the built-in robots; an export to a viewer needs the URDF itself (Foxglove draws the
robot from ``/robot_description``). The text is what :meth:`RobotModel.to_urdf` writes,
frames and boxes added in code included, so its links are the world's links. A robot
read from a file also keeps its description's values, so the run's robot is built again
when the file has moved, changed or never left another machine.
"""

from __future__ import annotations

import hashlib

from robocram.robots import RobotDescription, RobotModel
from robocram.robots.description_json import description_from_json, description_to_json
from robocram.traces.database import TraceDatabase
from robocram.traces.schema import RobotDescriptionRow, RobotModelRow

INSERT_MODEL = (
    f"INSERT OR IGNORE INTO {RobotModelRow.__tablename__} (digest, name, urdf) "
    "VALUES (:digest, :name, :urdf)"
)
INSERT_DESCRIPTION = (
    f"INSERT OR IGNORE INTO {RobotDescriptionRow.__tablename__} (digest, name, description) "
    "VALUES (:digest, :name, :description)"
)


def urdf_digest(model: RobotModel) -> str:
    """The SHA-1 (hex) of ``model``'s URDF text; kept with the model, computed once."""
    return model.derived(_digest)


def _digest(model: RobotModel) -> str:
    return hashlib.sha1(model.to_urdf().encode("utf-8")).hexdigest()


def model_row(name: str, model: RobotModel) -> dict[str, str]:
    """The ``robot_models`` row of ``model`` (for :data:`INSERT_MODEL`)."""
    return {"digest": urdf_digest(model), "name": name, "urdf": model.to_urdf()}


def description_row(desc: RobotDescription) -> dict[str, str]:
    """The ``robot_descriptions`` row of ``desc`` (for :data:`INSERT_DESCRIPTION`)."""
    text = description_to_json(desc)
    digest = hashlib.sha1(text.encode("utf-8")).hexdigest()
    return {"digest": digest, "name": desc.name, "description": text}


def stored_urdf(db: TraceDatabase, digest: str) -> str | None:
    """The URDF text stored under ``digest``, or ``None`` if the file has none."""
    with db.read() as session:
        row = session.get(RobotModelRow, digest)
        return None if row is None else row.urdf


def stored_description(
    db: TraceDatabase, digest: str, urdf_digest: str, source: str = ""
) -> RobotDescription | None:
    """The description stored under ``digest`` with the model of URDF ``urdf_digest``;
    ``None`` if the file keeps either not (a trace of an older robocram).

    The model is the stored URDF text read again: the same links, joints and meshes; an
    angle written as roll-pitch-yaw may differ from the run's in its 16th digit.
    """
    with db.read() as session:
        row = session.get(RobotDescriptionRow, digest)
        urdf = session.get(RobotModelRow, urdf_digest)
        if row is None or urdf is None:
            return None
        name, text, xml = row.name, row.description, urdf.urdf
    model = RobotModel.from_string(xml, source=f"{db.path} (robot {name!r} as it ran)")
    return description_from_json(text, model, source)
