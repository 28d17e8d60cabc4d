"""Where robocram's ROS 2 (Jazzy) lives, and how a process that uses it is started.

ROS 1's generated messages are on the venv's path (``robocram_ros.pth``) and ROS 2's
wheels define Python packages of the same names (``std_msgs``, ``geometry_msgs``, ...);
one interpreter can import only one of each. So ROS 2 is installed into a prefix of its
own, ``<venv>/ros2`` (``tools/setup_ros2.sh``), that the plan process never imports from:
only our ROS 2 node and the ROS 2 driver, child processes, run with it on their path and
with ROS 1's paths taken off theirs (docs/architecture.md).
"""

from __future__ import annotations

import os
import site
import sys
from dataclasses import dataclass
from pathlib import Path

from robocram.ros.errors import RosArgumentError, RosExtraMissing

PREFIX_VARIABLE = "ROBOCRAM_ROS2_PREFIX"  # overrides <venv>/ros2
HIDDEN_VARIABLE = "ROBOCRAM_HIDDEN_PATHS"  # ROS 1's path entries, taken off a child's path
ROS1_PTH = "robocram_ros.pth"
PROFILE_VARIABLE = "FASTRTPS_DEFAULT_PROFILES_FILE"  # ours (quick discovery) unless set
INTERFACES = ("rclpy", "control_msgs", "nav2_msgs", "tf2_msgs", "robocram_msgs")
SETUP_HINT = (
    "set it up with `make setup` (or `bash tools/setup_ros2.sh .venv`): it pip-installs ROS 2 "
    "Jazzy into .venv/ros2 and generates control_msgs, nav2_msgs and tf2_msgs there"
)
# First statements of every ROS 2 child: take ROS 1's entries (added by the venv's .pth)
# off the path before anything imports std_msgs.
BOOT = (
    "import os, sys; hidden = set(os.environ.get('ROBOCRAM_HIDDEN_PATHS', '').split(os.pathsep))"
    "; sys.path[:] = [p for p in sys.path if p not in hidden]; "
)


@dataclass(frozen=True)
class Ros2Prefix:
    """An installed ROS 2 prefix: its Python packages, libraries and ament index."""

    root: Path

    @property
    def site_packages(self) -> Path:
        """The prefix's Python packages (rclpy, the messages)."""
        version = f"python{sys.version_info[0]}.{sys.version_info[1]}"
        return self.root / "lib" / version / "site-packages"

    def missing(self) -> list[str]:
        """The packages robocram's ROS 2 side needs that the prefix lacks."""
        return [name for name in INTERFACES if not (self.site_packages / name).is_dir()]

    def library_path(self) -> list[str]:
        """The directories of the prefix's shared libraries (the wheels' vendored ones too)."""
        vendored = sorted(str(p) for p in self.site_packages.glob("ros_*.libs") if p.is_dir())
        return [str(self.root / "lib"), *vendored]

    def environment(self, domain_id: int, base: dict[str, str] | None = None) -> dict[str, str]:
        """The environment of a child process on ROS 2 domain ``domain_id`` (0..101)."""
        if not 0 <= domain_id <= 101:
            raise RosArgumentError(f"ROS_DOMAIN_ID must be in 0..101, got {domain_id}")
        env = dict(os.environ if base is None else base)
        hidden = ros1_paths()
        python_path = [str(self.site_packages)]
        python_path += [p for p in sys.path if p and p not in hidden]
        libraries = self.library_path() + [
            p for p in env.get("LD_LIBRARY_PATH", "").split(":") if p
        ]
        env.update(
            PYTHONPATH=os.pathsep.join(python_path),
            LD_LIBRARY_PATH=os.pathsep.join(libraries),
            AMENT_PREFIX_PATH=str(self.root),
            ROS_DOMAIN_ID=str(domain_id),
            _ROS_WHEELS_BOOTSTRAP_COMPLETE="1",  # the wheels' re-exec hook: done here
        )
        env[HIDDEN_VARIABLE] = os.pathsep.join(sorted(hidden))
        env.setdefault(PROFILE_VARIABLE, str(Path(__file__).with_name("fastdds_profile.xml")))
        return env


def ros1_paths() -> set[str]:
    """The path entries ROS 1's ``.pth`` file adds to the venv (empty without ROS 1)."""
    entries: set[str] = set()
    for directory in [*site.getsitepackages(), site.getusersitepackages()]:
        pth = Path(directory) / ROS1_PTH
        if pth.is_file():
            entries.update(line.strip() for line in pth.read_text().splitlines() if line.strip())
    return entries


def ros2_prefix() -> Ros2Prefix:
    """The ROS 2 prefix: ``$ROBOCRAM_ROS2_PREFIX``, else ``<venv>/ros2``."""
    configured = os.environ.get(PREFIX_VARIABLE)
    return Ros2Prefix(Path(configured) if configured else Path(sys.prefix) / "ros2")


def require_ros2() -> Ros2Prefix:
    """The ROS 2 prefix, or :class:`RosExtraMissing` naming what lacks and the command."""
    prefix = ros2_prefix()
    missing = prefix.missing()
    if missing:
        raise RosExtraMissing(
            f"ROS 2 for robocram.ros is not set up in {prefix.root} (no {', '.join(missing)}); "
            f"{SETUP_HINT}"
        )
    return prefix


def child_argv(code: str) -> list[str]:
    """A fresh interpreter that takes ROS 1 off its path, then runs ``code``."""
    return [sys.executable, "-c", BOOT + code]
