"""A real Ray cluster on this machine for the fault tests: a head and worker nodes, each a
separate raylet started by ``ray start``, each node with its own temporary directory, so a
node's processes can be found, and killed, by that directory.

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
from pathlib import Path

import psutil

RAY = str(Path(sys.executable).with_name("ray"))
START_LIMIT = 90.0  # [s] for one `ray start`; a guard against a hang, not a measure
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
        self._killed: list[psutil.Process] = []  # a killed node's processes, orphaned now

    def start_head(self, cpus: int) -> None:
        """Start the head node with ``cpus`` CPUs for actors (0: it runs none)."""
        port = self.address.rsplit(":", 1)[1]
        # not the default ports 8265 and 10001: another Ray on the machine may hold them (a
        # Ray Client server runs where ray[client] is installed; the option needs it)
        ports = ["--dashboard-port", str(_free_port())]
        if importlib.util.find_spec("grpc") is not None:
            ports += ["--ray-client-server-port", str(_free_port())]
        self._ray_start(
            "--head", "--port", port, "--num-cpus", str(cpus), "--include-dashboard=false", *ports
        )

    def add_node(self, **env: str) -> str:
        """Start a one-CPU worker node with ``env`` added to its processes' environment;
        return its temporary directory (it names the node)."""
        return self._ray_start("--address", self.address, "--num-cpus", "1", **env)

    def _ray_start(self, *args: str, **env: str) -> str:
        temp = tempfile.mkdtemp(prefix="rc-ray-", dir="/tmp")
        self._dirs.append(temp)
        command = [RAY, "start", *args, "--temp-dir", temp]
        done = subprocess.run(
            command, env={**self.env, **env}, capture_output=True, text=True, timeout=START_LIMIT
        )
        if done.returncode != 0:
            raise RuntimeError(f"{' '.join(command)} failed:\n{done.stdout}\n{done.stderr}")
        return temp

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
        processes = [*self._killed, *(p for temp in self._dirs for p in self._processes(temp))]
        for process in processes:
            with contextlib.suppress(psutil.NoSuchProcess):
                process.kill()
        psutil.wait_procs(processes, timeout=10.0)
        for temp in self._dirs:
            shutil.rmtree(temp, ignore_errors=True)
