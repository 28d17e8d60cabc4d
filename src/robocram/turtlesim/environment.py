"""Turtle environments: the same plans, two different robots.

``turtle_environment(world)`` is the exact simulated turtle. ``noisy_turtle_environment``
stands for a real one: its navigation module has another name, its matching facts send
``moving`` and ``driving`` there, and it misses goals by Gaussian noise and logs.
"""

from __future__ import annotations

from collections.abc import Callable
from importlib import resources

from robocram.designators import install_designator_predicates
from robocram.execution.environment import Environment
from robocram.execution.perform import register_plan
from robocram.execution.process_module import ProcessModule
from robocram.execution.process_module_matching import install_process_module_interface
from robocram.logic import KnowledgeBase, name_atom
from robocram.turtlesim.locations import turtle_location_resolver
from robocram.turtlesim.plans import draw_house, navigate
from robocram.turtlesim.process_modules import (
    NoisyTurtleNavigationPM,
    TurtleNavigationPM,
    TurtlePenPM,
)
from robocram.turtlesim.world import TurtleWorld

TURTLE_GROUP = "turtle_groundings"


def turtle_knowledge_base() -> KnowledgeBase:
    """Return a knowledge base with the turtle's groundings and plans."""
    kb = KnowledgeBase()
    install_designator_predicates(kb)
    install_process_module_interface(kb)
    text = resources.files("robocram.turtlesim").joinpath("turtle.pl").read_text()
    kb.consult(text, group=TURTLE_GROUP)
    register_plan(kb, "navigate", navigate)
    register_plan(kb, "draw_house", draw_house)
    return kb


def _matching_facts(navigation_name: str) -> str:
    navigation = name_atom(navigation_name)
    return f"""
matching_process_module(D, {navigation}) :- desig_prop(D, type, driving).
matching_process_module(D, {navigation}) :- desig_prop(D, type, moving).
matching_process_module(D, turtle_pen) :- desig_prop(D, type, 'setting-pen').
available_process_module({navigation}).
available_process_module(turtle_pen).
"""


def _environment(
    name: str, world: TurtleWorld, navigation: ProcessModule, seed: int | None
) -> Environment:
    return Environment(
        name,
        process_modules=(navigation, TurtlePenPM(world)),
        facts=_matching_facts(navigation.name),
        kb=turtle_knowledge_base(),
        location_resolver=turtle_location_resolver(world.size, seed),
    )


def turtle_environment(world: TurtleWorld, seed: int | None = None) -> Environment:
    """Return the exact turtle: navigation and pen modules on ``world``.

    ``seed`` fixes the random points location designators resolve to.
    """
    return _environment("turtle", world, TurtleNavigationPM(world), seed)


def noisy_turtle_environment(
    world: TurtleWorld,
    sigma: float = 0.05,
    seed: int | None = None,
    log: Callable[[str], None] | None = None,
) -> Environment:
    """Return a turtle whose navigation misses goals by ``sigma`` [m] and logs to ``log``."""
    navigation = NoisyTurtleNavigationPM(world, sigma=sigma, seed=seed, log=log)
    return _environment("noisy_turtle", world, navigation, seed)
