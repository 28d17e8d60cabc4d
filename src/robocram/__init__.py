"""robocram: CRAM, the Cognitive Robot Abstract Machine, in Python.

Layers, lowest first: ``logic`` and ``tf``; ``designators`` and ``robots``;
``execution`` and ``world``; ``kinematics``; ``projection``; ``turtlesim``.
A layer imports only from layers below it (``tests/test_layering.py`` checks).
"""

__version__ = "0.1.0"
