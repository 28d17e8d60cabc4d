#!/usr/bin/env bash
# Set up robocram.ros in a virtual environment: ROS 1 (Noetic generation) from Debian's
# packages, control_msgs and robocram_msgs generated with genpy, and a .pth file that puts
# them and Debian's ROS Python packages on the venv's path (same Python minor version only).
# Idempotent: with everything in place it only checks, in about a second.
# Usage: bash tools/setup_ros.sh [VENV]   (default .venv)
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=${1:-.venv}
DEBIAN_PYTHON=/usr/bin/python3
PACKAGES=(ros-core python3-rospy python3-actionlib python3-tf2-ros python3-geometry-msgs
  python3-sensor-msgs python3-trajectory-msgs python3-move-base-msgs python3-genpy
  python3-genmsg ros-std-msgs ros-geometry-msgs ros-actionlib-msgs ros-trajectory-msgs)

missing=()
for package in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
if ((${#missing[@]})); then
  if [ "$(id -u)" != 0 ]; then
    echo "setup_ros: missing Debian packages ${missing[*]}; run this script as root" >&2
    exit 1
  fi
  echo "setup_ros: apt-get install ${missing[*]}"
  apt_get=(apt-get -o DPkg::Lock::Timeout=600 -y -q --no-install-recommends)
  "${apt_get[@]}" install "${missing[@]}" >/dev/null \
    || { apt-get -o DPkg::Lock::Timeout=600 -q update >/dev/null \
         && "${apt_get[@]}" install "${missing[@]}" >/dev/null; }
fi

minor() { "$1" -c 'import sys; print("%d.%d" % sys.version_info[:2])'; }
debian_minor=$(minor "$DEBIAN_PYTHON")
venv_minor=$(minor "$VENV/bin/python")
if [ "$debian_minor" != "$venv_minor" ]; then
  echo "setup_ros: Debian's ROS packages are built for Python $debian_minor but $VENV has" \
    "Python $venv_minor; recreate the venv with Python $debian_minor" >&2
  exit 1
fi

messages="$(cd "$VENV" && pwd)/ros_msgs"
"$DEBIAN_PYTHON" tools/generate_ros_messages.py "$messages"
dist_packages=$("$DEBIAN_PYTHON" -c \
  'import os, rospy; print(os.path.dirname(os.path.dirname(rospy.__file__)))')
site=$("$VENV/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
printf '%s\n%s\n' "$messages" "$dist_packages" > "$site/robocram_ros.pth"
"$VENV/bin/python" -c 'import rospy, actionlib, tf2_ros, move_base_msgs.msg, control_msgs.msg, robocram_msgs.msg'
