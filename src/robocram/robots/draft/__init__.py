"""Draft a robot description from a URDF: ``draft_description(urdf).source()``."""

from robocram.robots.draft.draft_description import DraftDescription, draft_description

__all__ = ["DraftDescription", "draft_description"]
