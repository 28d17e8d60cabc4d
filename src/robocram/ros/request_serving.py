"""How a node child process (ROS 1's or ROS 2's) answers the plan process's requests.

Both nodes speak one pipe protocol (``ros1_node.py`` describes it); the loop that reads a
request, runs the node's ``op_<name>`` and replies is the same for both, so it lives here
once. Requests that wait on the robot (a goal, a state, settling) run on their own thread,
so a long one never holds up a quick lookup behind it."""

from __future__ import annotations

import threading
from multiprocessing.connection import Connection
from typing import Protocol

BLOCKING_OPS = frozenset({"send_goal", "wait_for_state", "settle"})


class Serving(Protocol):
    """A node that answers the pipe's requests (``op_<name>`` methods): ROS 1's or ROS 2's."""

    running: bool

    def send(self, message: tuple[object, ...]) -> None:
        """Write one message to the plan process."""
        ...


def handle_request(node: Serving, request_id: int, op: str, args: tuple[object, ...]) -> None:
    """Run ``node.op_<op>(*args)`` and send its reply (an error is a failed reply)."""
    try:
        payload = getattr(node, f"op_{op}")(*args)
    except Exception as err:  # the reply carries it to the plan process
        node.send(("reply", request_id, False, f"{type(err).__name__}: {err}"))
    else:
        node.send(("reply", request_id, True, payload))


def serve_requests(conn: Connection, node: Serving) -> None:
    """Answer requests from ``conn`` until the node stops or the plan process has gone."""
    while node.running:
        try:
            request_id, op, args = conn.recv()
        except (EOFError, OSError):
            break
        if op in BLOCKING_OPS:
            threading.Thread(
                target=handle_request, args=(node, request_id, op, args), daemon=True
            ).start()
        else:
            handle_request(node, request_id, op, args)
