"""robocram: CRAM, the Cognitive Robot Abstract Machine, in Python.

Layers, lowest first: ``logic`` and ``tf``; ``designators`` and ``robots``;
``execution`` and ``world``; ``kinematics``; ``projection``; ``turtlesim``.
A layer imports only from layers below it (``tests/test_layering.py`` checks).
Importing robocram first keeps dataclasses' generated methods compiled on disk
(:mod:`robocram.dataclass_code`): nearly half of what importing the plans cost.
"""

from robocram.dataclass_code import install as _install_dataclass_code

__version__ = "0.1.0"

_install_dataclass_code()
