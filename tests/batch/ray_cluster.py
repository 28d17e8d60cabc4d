"""A real Ray cluster on this machine for the fault tests: a head and worker nodes, each a
separate raylet started by ``ray start``, each node with its own temporary directory, so a
node's processes can be found, and killed, by that directory. Worker nodes start side by
side (each ``ray start`` mostly waits for its node to come up), and a test's nodes can be
removed, so tests of a module share one head.

Only the processes of this cluster are ever killed (never ``ray stop``, which would stop
every Ray of this user on the machine).
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path

import psutil

RAY = str(Path(sys.executable).with_name("ray"))
START_LIMIT = 90.0  # [s] for one `ray start`; a guard against a hang, not a measure
DEAD_LIMIT = 60.0  # [s] for the head to declare removed nodes dead; a guard, not a measure
# the head's GCS checks each node from its start and every 0.2 s (Ray's defaults: after
# 5 s, every 3 s), so a killed raylet, which refuses at once, is declared dead within a
# second, not ~3.5 s; the timeout of a check and the failures needed stay Ray's (a slow
# but live raylet is not declared dead any sooner)
HEALTH_CHECKS = {"RAY_health_check_initial_delay_ms": "0", "RAY_health_check_period_ms": "200"}


# ports Ray's components take by default (the dashboard agent's HTTP 52365, GCS 6379, the
# dashboard 8265, the client server 10001, metrics 8080) and its workers' range
RAY_DEFAULT_PORTS = {52365, 6379, 8265, 10001, 8080, *range(10002, 20000)}


def _free_port() -> int:
    """A free port none of Ray's components takes by default (the OS may hand out 52365,
    and `ray start` then refuses two components on one port)."""
    while True:
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            port = int(s.getsockname()[1])
        if port not in RAY_DEFAULT_PORTS:
            return port


class LocalCluster:
    """``ray start --head`` and ``ray start --address`` nodes; :meth:`stop` ends them all."""

    def __init__(self) -> None:
        # the nodes authenticate as this process will: Ray reads the mode once per process,
        # and a local `ray.init()` turns tokens on in it (its token in ~/.ray/auth_token)
        mode = os.environ.get("RAY_AUTH_MODE", "disabled")
        self.env = {
            **os.environ,
            "RAY_AUTH_MODE": mode,
            "RAY_USAGE_STATS_ENABLED": "0",
            **HEALTH_CHECKS,
        }
        self.address = f"127.0.0.1:{_free_port()}"
        self._dirs: list[str] = []  # short: Ray's socket paths must stay under 108 bytes
        self._head = ""  # the head's directory, once started
        self._removed: list[str] = []  # removed nodes' directories, deleted by stop()
        self._killed: list[psutil.Process] = []  # a killed node's processes, orphaned now

    def start_head(self, cpus: int) -> None:
        """Start the head node with ``cpus`` CPUs for actors (0: it runs none)."""
        port = self.address.rsplit(":", 1)[1]
        # not the default ports 8265 and 10001: another Ray on the machine may hold them (a
        # Ray Client server runs where ray[client] is installed; the option needs it)
        ports = ["--dashboard-port", str(_free_port())]
        if importlib.util.find_spec("grpc") is not None:
            ports += ["--ray-client-server-port", str(_free_port())]
        (self._head,) = self._ray_start(
            [
                (
                    "--head",
                    "--port",
                    port,
                    "--num-cpus",
                    str(cpus),
                    "--include-dashboard=false",
                    *ports,
                )
            ],
            [{}],
        )

    def add_node(self, **env: str) -> str:
        """Start a one-CPU worker node with ``env`` added to its processes' environment;
        return its temporary directory (it names the node)."""
        (temp,) = self.add_nodes([env])
        return temp

    def add_nodes(self, envs: Sequence[dict[str, str]]) -> list[str]:
        """Start one one-CPU worker node per ``envs`` entry (added to its processes'
        environment), side by side; return their temporary directories, in that order."""
        node = ("--address", self.address, "--num-cpus", "1")
        return self._ray_start([node] * len(envs), envs)

    def _ray_start(
        self, argvs: Sequence[Sequence[str]], envs: Sequence[dict[str, str]]
    ) -> list[str]:
        """Run one ``ray start`` per ``argvs`` entry at once; their directories."""
        temps = [tempfile.mkdtemp(prefix="rc-ray-", dir="/tmp") for _ in argvs]
        self._dirs.extend(temps)
        commands = [
            [RAY, "start", *args, "--temp-dir", t] for args, t in zip(argvs, temps, strict=True)
        ]
        started = [
            subprocess.Popen(
                c,
                env={**self.env, **env},
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
                text=True,
            )
            for c, env in zip(commands, envs, strict=True)
        ]
        for command, process in zip(commands, started, strict=True):
            out, err = process.communicate(timeout=START_LIMIT)
            if process.returncode != 0:
                raise RuntimeError(f"{' '.join(command)} failed:\n{out}\n{err}")
        return temps

    @property
    def has_nodes(self) -> bool:
        """Whether worker nodes were added (and not removed) to the head."""
        return any(temp != self._head for temp in self._dirs)

    def remove_nodes(self, alive_nodes: Callable[[], int]) -> None:
        """SIGKILL every worker node's processes (the head's are kept; :meth:`stop` waits
        for them to exit) and wait until ``alive_nodes()`` (the head's count of live nodes)
        is 1: the next test's nodes are the only ones its actors can be placed on."""
        for temp in self._dirs:
            if temp != self._head:
                processes = self._processes(temp)
                self._killed.extend(processes)
                for process in processes:
                    with contextlib.suppress(psutil.NoSuchProcess):
                        process.kill()
                self._removed.append(temp)
        self._dirs = [self._head]
        deadline = time.monotonic() + DEAD_LIMIT
        while alive_nodes() > 1:
            if time.monotonic() > deadline:
                raise RuntimeError(
                    f"the head still counts removed nodes alive after {DEAD_LIMIT} s"
                )
            time.sleep(0.1)

    def kill_node(self, temp: str) -> int:
        """SIGKILL the raylet of the node started in ``temp``; return its pid."""
        processes = self._processes(temp)
        (raylet,) = [p for p in processes if p.name() == "raylet"]
        self._killed.extend(processes)  # its workers no longer name the directory
        raylet.kill()
        return raylet.pid

    def _processes(self, temp: str) -> list[psutil.Process]:
        """The processes of one node: those naming its directory, and their children."""
        found: dict[int, psutil.Process] = {}
        for process in psutil.process_iter(["cmdline"]):
            if temp in " ".join(process.info["cmdline"] or []):
                found[process.pid] = process
                with contextlib.suppress(psutil.NoSuchProcess):
                    found.update((c.pid, c) for c in process.children(recursive=True))
        return list(found.values())

    def stop(self) -> None:
        """Kill every process of every node and remove their directories."""
        self._kill([*self._killed, *(p for temp in self._dirs for p in self._processes(temp))])
        for temp in [*self._dirs, *self._removed]:
            shutil.rmtree(temp, ignore_errors=True)

    @staticmethod
    def _kill(processes: list[psutil.Process]) -> None:
        """SIGKILL ``processes`` and wait (a while) for them to exit."""
        for process in processes:
            with contextlib.suppress(psutil.NoSuchProcess):
                process.kill()
        psutil.wait_procs(processes, timeout=10.0)
