"""Draft a robot description from a URDF: ``robocram.robots.draft_description(urdf).source()``.

Nothing is imported here: projection reads a few of the draft's findings (a legged
robot's feet, :mod:`~robocram.robots.draft.stance`) for every robot it sets up, and the
whole drafter (28 modules, numpy's random generators) is for drafting only.
"""
