"""A scene built while another lives shares its parsed URDFs (the model memo holds models
only weakly, so the scene, its world's bodies and its robot are what keep them; that a
model nobody holds is not kept is tests/robots/test_model_memo.py's)."""

from __future__ import annotations

from robocram.scenes import kitchen_scene


def test_a_scene_built_while_another_lives_shares_its_parses() -> None:
    first = kitchen_scene("pr2")
    second = kitchen_scene("pr2")
    try:
        assert first.checked is not None and second.checked is first.checked
        kitchen = second.world.object(second.kitchen).urdf_model
        assert kitchen is not None and kitchen is first.world.object(first.kitchen).urdf_model
        robot = second.world.robot(second.robot).description.model
        assert robot is first.world.robot(first.robot).description.model
    finally:
        first.world.close()
        second.world.close()


def test_a_scene_parses_its_environment_once() -> None:
    scene = kitchen_scene("pr2")
    try:  # the check read the file as the world's load does: the load shares that model
        assert scene.world.object(scene.kitchen).urdf_model is scene.checked
    finally:
        scene.world.close()
