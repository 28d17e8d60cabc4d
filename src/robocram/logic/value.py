"""``Value``: what a Prolog term is on the Python side, said once.

A query answer binds each variable to whatever the term maps to: an atom as ``str``, a
number as ``int`` or ``float``, a list as ``list``, a compound as ``Term``, or any Python
object the knowledge base holds (a world, a pose, a designator). Arguments of Python
predicates are the same. No narrower type covers all of these, so the seam between Python
and Prolog is typed ``Value`` rather than a bare ``Any`` repeated at every site.
"""

from __future__ import annotations

from typing import Any

# Any on purpose: a Prolog-mapped value really can be any Python value (see above).
Value = Any
