"""The current transform tree, bound dynamically like CRAM's ``*transformer*``.

Projection rebinds the transformer to the simulated world's tree; code below it calls
:func:`transform_pose` without passing the tree around. A :class:`contextvars.ContextVar`
keeps the binding per thread and per task.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

from robocram.tf.errors import TfError, TfUsageError
from robocram.tf.stamped import PoseStamped
from robocram.tf.transform_tree import TransformTree

_CURRENT_TREE: ContextVar[TransformTree | None] = ContextVar(
    "robocram_transform_tree", default=None
)


def current_transform_tree() -> TransformTree:
    """The tree bound by the innermost :func:`using_transform_tree`; raise if none is."""
    tree = _CURRENT_TREE.get()
    if tree is None:
        raise TfError(
            "no transform tree is bound; wrap the call in `with using_transform_tree(tree):` "
            "or pass tree= explicitly"
        )
    return tree


@contextmanager
def using_transform_tree(tree: TransformTree) -> Iterator[TransformTree]:
    """Bind ``tree`` as the current transform tree inside the ``with`` block."""
    if not isinstance(tree, TransformTree):
        raise TfUsageError(f"using_transform_tree needs a TransformTree, got {tree!r}")
    token = _CURRENT_TREE.set(tree)
    try:
        yield tree
    finally:
        _CURRENT_TREE.reset(token)


def transform_pose(
    pose: PoseStamped, target_frame: str, tree: TransformTree | None = None
) -> PoseStamped:
    """Express ``pose`` in ``target_frame`` using ``tree`` or the current tree.

    >>> from robocram.tf import Pose
    >>> t = TransformTree()
    >>> t.set_transform("map", "table", Pose((2, 0, 0.8)))
    >>> transform_pose(PoseStamped("table", (0.1, 0, 0)), "map", t).position
    (2.1, 0.0, 0.8)
    """
    return (tree if tree is not None else current_transform_tree()).transform_pose(
        pose, target_frame
    )
