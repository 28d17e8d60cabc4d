"""Draw "das Haus vom Nikolaus" with the tutorial turtle and print the task tree.

One PERFORM of ``(an action (type drawing) (shape house))``: the turtle's knowledge base
grounds it to a plan of nine ``navigating`` actions, each a ``moving`` motion that the
navigation process module executes by stepping the simulator.
"""

from __future__ import annotations

from robocram.designators import an
from robocram.execution import TopLevel, perform
from robocram.turtlesim import TurtleWorld, turtle_environment


def main() -> None:
    """Draw the house, then print the strokes and the task tree."""
    world = TurtleWorld()
    with turtle_environment(world):
        drawing = TopLevel("draw-house")
        drawing.run(
            lambda: perform(an.action(type="drawing", shape="house", origin=(3, 2), size=4))
        )
        tree = drawing.tree
    for i, line in enumerate(world.lines, 1):
        print(
            f"stroke {i}: ({line.start[0]:.2f}, {line.start[1]:.2f}) -> "
            f"({line.end[0]:.2f}, {line.end[1]:.2f})"
        )
    print(tree.render())


if __name__ == "__main__":
    main()
