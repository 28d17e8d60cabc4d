"""Robot models as the trace store keeps them: each URDF text once, named by its digest.

A scene records a robot by its description's name, which is enough to rebuild the world
from the built-in robots; an export to a viewer needs the URDF itself (Foxglove draws the
robot from ``/robot_description``). The text is what :meth:`RobotModel.to_urdf` writes,
frames and boxes added in code included, so its links are the world's links.
"""

from __future__ import annotations

import hashlib

from robocram.robots import RobotModel
from robocram.traces.database import TraceDatabase
from robocram.traces.schema import RobotModelRow

INSERT_MODEL = (
    f"INSERT OR IGNORE INTO {RobotModelRow.__tablename__} (digest, name, urdf) "
    "VALUES (:digest, :name, :urdf)"
)


def urdf_digest(model: RobotModel) -> str:
    """The SHA-1 (hex) of ``model``'s URDF text; kept with the model, computed once."""
    return model.derived(_digest)


def _digest(model: RobotModel) -> str:
    return hashlib.sha1(model.to_urdf().encode("utf-8")).hexdigest()


def model_row(name: str, model: RobotModel) -> dict[str, str]:
    """The ``robot_models`` row of ``model`` (for :data:`INSERT_MODEL`)."""
    return {"digest": urdf_digest(model), "name": name, "urdf": model.to_urdf()}


def stored_urdf(db: TraceDatabase, digest: str) -> str | None:
    """The URDF text stored under ``digest``, or ``None`` if the file has none."""
    with db.read() as session:
        row = session.get(RobotModelRow, digest)
        return None if row is None else row.urdf
