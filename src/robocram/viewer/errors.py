"""Errors of the browser viewer: one root, each naming the culprit and the fix."""

from __future__ import annotations


class ViewerError(Exception):
    """Root of every viewer error."""


class PortInUse(ViewerError):  # noqa: N818 - reads as what happened
    """The viewer's port is taken by another program."""

    def __init__(self, host: str, port: int) -> None:
        super().__init__(
            f"port {port} on {host} is in use; stop the program holding it or choose "
            f"another with --port (Viewer(port=...))"
        )
        self.host, self.port = host, port


class NoWorld(ViewerError):  # noqa: N818
    """A viewer needs a world to draw."""

    def __init__(self) -> None:
        super().__init__(
            "the viewer has no world to show; start it with a world (Viewer(world)), run "
            "`robocram view` for the live demo, or `robocram replay DB --run N` for a stored run"
        )


class ViewerUnavailable(ViewerError):  # noqa: N818
    """The optional viewer packages are not installed."""

    def __init__(self, missing: str) -> None:
        super().__init__(
            f"the browser viewer needs {missing!r}; install it with pip install 'robocram[viewer]'"
        )


class ViewerArgumentError(ViewerError, ValueError):
    """A value given to the viewer is outside what it accepts."""

    summary = "a value given to the viewer is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class ViewerUnknownKey(ViewerError, KeyError):
    """A name that the viewer does not know; the message lists the known ones."""

    summary = "a name that the viewer does not know"
    hint = "use one of the names the message lists"
