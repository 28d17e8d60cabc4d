"""Generate the Python ROS 1 messages Debian does not package: control_msgs, the PR2's
pr2_controllers_msgs and robocram_msgs.

Run with Debian's interpreter (it has genmsg and genpy):
``/usr/bin/python3 tools/generate_ros_messages.py OUT_DIR``. Each ``.action`` becomes its
seven messages (Goal, Result, Feedback and the Action/ActionGoal/ActionResult/ActionFeedback
wrappers with a header and a goal id or status), then genpy writes the Python packages
``OUT_DIR/control_msgs``, ``OUT_DIR/pr2_controllers_msgs`` and ``OUT_DIR/robocram_msgs``.
Dependencies (std_msgs, geometry_msgs, actionlib_msgs, trajectory_msgs) come from Debian's
``/usr/share/<pkg>/msg``.
A stamp file holding the hash of the definitions makes a second run a no-op.
"""

from __future__ import annotations

import hashlib
import sys
from pathlib import Path

DEFINITIONS = Path(__file__).resolve().parents[1] / "src" / "robocram" / "ros" / "definitions"
PACKAGES = ("control_msgs", "pr2_controllers_msgs", "robocram_msgs")
DEPENDENCIES = ("std_msgs", "geometry_msgs", "actionlib_msgs", "trajectory_msgs")
SYSTEM_SHARE = Path("/usr/share")


def definitions_hash() -> str:
    """Hash of every definition file and of this script, to know when to regenerate."""
    digest = hashlib.sha256(Path(__file__).read_bytes())
    for path in sorted(DEFINITIONS.rglob("*.*")):
        digest.update(path.relative_to(DEFINITIONS).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


def action_messages(name: str, text: str) -> dict[str, str]:
    """The seven message definitions an action ``name`` with ``text`` stands for."""
    parts: list[list[str]] = [[]]
    for line in text.splitlines():
        if line.strip() == "---":
            parts.append([])
        else:
            parts[-1].append(line)
    if len(parts) != 3:
        raise SystemExit(f"{name}.action must have goal, result and feedback parts split by ---")
    goal, result, feedback = ("\n".join(p) + "\n" for p in parts)
    return {
        f"{name}Goal": goal,
        f"{name}Result": result,
        f"{name}Feedback": feedback,
        f"{name}ActionGoal": f"Header header\nactionlib_msgs/GoalID goal_id\n{name}Goal goal\n",
        f"{name}ActionResult": (
            f"Header header\nactionlib_msgs/GoalStatus status\n{name}Result result\n"
        ),
        f"{name}ActionFeedback": (
            f"Header header\nactionlib_msgs/GoalStatus status\n{name}Feedback feedback\n"
        ),
        f"{name}Action": (
            f"{name}ActionGoal action_goal\n{name}ActionResult action_result\n"
            f"{name}ActionFeedback action_feedback\n"
        ),
    }


def expand(package: str, build: Path) -> list[Path]:
    """Write ``package``'s messages, actions expanded, into ``build/package/msg``."""
    out = build / package / "msg"
    out.mkdir(parents=True, exist_ok=True)
    files = []
    for path in sorted((DEFINITIONS / package / "msg").glob("*.msg")):
        target = out / path.name
        target.write_text(path.read_text())
        files.append(target)
    for path in sorted((DEFINITIONS / package / "action").glob("*.action")):
        for name, text in action_messages(path.stem, path.read_text()).items():
            target = out / f"{name}.msg"
            target.write_text(text)
            files.append(target)
    return files


def search_path(build: Path) -> dict[str, list[str]]:
    """Where genmsg finds each package's ``.msg`` files."""
    paths = {}
    for dep in DEPENDENCIES:
        directory = SYSTEM_SHARE / dep / "msg"
        if not directory.is_dir():
            raise SystemExit(f"{directory} is missing: apt-get install ros-{dep.replace('_', '-')}")
        paths[dep] = [str(directory)]
    for package in PACKAGES:
        paths[package] = [str(build / package / "msg")]
    return paths


def generate(out_dir: Path) -> None:
    """Generate the Python packages into ``out_dir`` unless they are up to date."""
    from genpy.generate_initpy import write_modules
    from genpy.generator import MsgGenerator

    stamp = out_dir / ".definitions-hash"
    wanted = definitions_hash()
    if stamp.is_file() and stamp.read_text() == wanted:
        return
    build = out_dir / ".definitions"
    files = {package: expand(package, build) for package in PACKAGES}
    paths = search_path(build)
    for package, package_files in files.items():
        target = out_dir / package / "msg"
        code = MsgGenerator().generate_messages(
            package, [str(f) for f in package_files], str(target), paths
        )
        if code:
            raise SystemExit(f"genpy failed on {package} (exit {code})")
        write_modules(str(target))
        (out_dir / package / "__init__.py").write_text("")
    stamp.write_text(wanted)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit("usage: /usr/bin/python3 tools/generate_ros_messages.py OUT_DIR")
    generate(Path(sys.argv[1]).resolve())
