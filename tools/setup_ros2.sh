#!/usr/bin/env bash
# Set up ROS 2 (Jazzy) for robocram.ros in a prefix of its own, VENV/ros2: rclpy and the
# common interfaces from the Python package index (wheels named ros-jazzy-*, no apt
# packages), then control_msgs, nav2_msgs, tf2_msgs and robocram_msgs generated with
# rosidl, cmake and gcc from src/robocram/ros/definitions2.
# The prefix is never on the venv's path: ROS 1's messages are (robocram_ros.pth), and both
# define std_msgs, geometry_msgs, ... Only robocram's ROS 2 child processes see it
# (robocram/ros/ros2_environment.py; docs/architecture.md).
# Idempotent: a second run that finds everything built only checks, in a few seconds.
# Usage: bash tools/setup_ros2.sh [VENV]   (default .venv)
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=$(cd "${1:-.venv}" && pwd)
PYTHON=$VENV/bin/python
PREFIX=$VENV/ros2
DEFINITIONS=src/robocram/ros/definitions2
INTERFACES=(robocram_msgs tf2_msgs nav2_msgs control_msgs)
WHEELS=("ros-jazzy-rclpy[fastrtps]" ros-jazzy-std-msgs ros-jazzy-geometry-msgs
  ros-jazzy-sensor-msgs ros-jazzy-trajectory-msgs ros-jazzy-action-msgs
  ros-jazzy-builtin-interfaces ros-jazzy-python-cmake-module ros-jazzy-ament-package
  # the generators: pip's dependency data for them is incomplete, so every one is named
  ros-jazzy-ament-cmake ros-jazzy-ament-cmake-{core,export-definitions,export-dependencies}
  ros-jazzy-ament-cmake-{export-include-directories,export-interfaces,export-libraries}
  ros-jazzy-ament-cmake-{export-link-flags,export-targets,gen-version-h,include-directories}
  ros-jazzy-ament-cmake-{libraries,python,ros,target-dependencies,test,version}
  ros-jazzy-ament-cmake-{gmock,gtest,pytest,vendor-package}
  ros-jazzy-rosidl-{adapter,cli,cmake,core-generators,core-runtime,default-generators}
  ros-jazzy-rosidl-{default-runtime,dynamic-typesupport,dynamic-typesupport-fastrtps}
  ros-jazzy-rosidl-{generator-c,generator-cpp,generator-py,generator-type-description}
  ros-jazzy-rosidl-{parser,pycommon,runtime-c,runtime-cpp,typesupport-c,typesupport-cpp}
  ros-jazzy-rosidl-typesupport-{fastrtps-c,fastrtps-cpp,interface,introspection-c}
  ros-jazzy-rosidl-typesupport-introspection-cpp catkin_pkg)

version=$("$PYTHON" -c 'import sys; print("%d.%d" % sys.version_info[:2])')
SITE=$PREFIX/lib/python$version/site-packages
libraries=$PREFIX/lib
for libs in "$SITE"/ros_*.libs; do [ -d "$libs" ] && libraries=$libraries:$libs; done
run() {  # a command in the ROS 2 prefix's environment
  env PYTHONPATH="$SITE" LD_LIBRARY_PATH="$libraries" AMENT_PREFIX_PATH="$PREFIX" \
    CMAKE_PREFIX_PATH="$PREFIX" PATH="$PREFIX/bin:$VENV/bin:$PATH" "$@"
}
check() {  # imports as robocram's ROS 2 processes do: without ROS 1's paths
  run "$PYTHON" -c '
import sys
sys.path[:] = [p for p in sys.path if not p.endswith("ros_msgs") and "dist-packages" not in p]
import rclpy, control_msgs.action, nav2_msgs.action, tf2_msgs.msg, robocram_msgs.action
import sensor_msgs.msg, trajectory_msgs.msg
assert control_msgs.__file__.startswith(sys.argv[1]), control_msgs.__file__
' "$PREFIX"
}
fingerprint() {  # of everything a build depends on: this script, the definitions, the fix
  cat "$0" tools/ros2_cmake_fix.cmake "$DEFINITIONS/$1"/*/* "$DEFINITIONS/$1"/*.* \
    | sha256sum | cut -c1-16
}

wheels_stamp=$PREFIX/.wheels-$(printf '%s\n' "${WHEELS[@]}" | sha256sum | cut -c1-16)
if [ ! -e "$wheels_stamp" ]; then
  echo "setup_ros2: pip install ROS 2 Jazzy wheels into $PREFIX"
  # PYTHONPATH shows pip what the prefix holds already; the venv's own packages (numpy,
  # PyYAML, empy, catkin_pkg) satisfy the rest and are left as they are.
  PYTHONPATH=$SITE "$PYTHON" -m pip install -qq --prefix "$PREFIX" \
    --no-warn-script-location "${WHEELS[@]}"
  libraries=$PREFIX/lib
  for libs in "$SITE"/ros_*.libs; do [ -d "$libs" ] && libraries=$libraries:$libs; done
  touch "$wheels_stamp"
fi

for package in "${INTERFACES[@]}"; do
  stamp=$PREFIX/.built-$package-$(fingerprint "$package")
  [ -e "$stamp" ] && continue
  echo "setup_ros2: generating $package (rosidl, cmake, gcc)"
  build=$PREFIX/build/$package
  rm -rf "$build" && mkdir -p "$build"
  run cmake -S "$DEFINITIONS/$package" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_INSTALL_PREFIX="$PREFIX" \
    -DPython3_EXECUTABLE="$PYTHON" -DBUILD_TESTING=OFF \
    -DCMAKE_PROJECT_INCLUDE="$(pwd)/tools/ros2_cmake_fix.cmake" >"$build.log" 2>&1 \
    || { tail -30 "$build.log" >&2; exit 1; }
  run cmake --build "$build" -j "$(nproc)" >>"$build.log" 2>&1 \
    || { tail -30 "$build.log" >&2; exit 1; }
  run cmake --install "$build" >>"$build.log" 2>&1 || { tail -30 "$build.log" >&2; exit 1; }
  rm -f "$PREFIX/.built-$package-"* && touch "$stamp"
done

check || { echo "setup_ros2: the ROS 2 prefix $PREFIX does not import; remove it and run" \
  "this again" >&2; exit 1; }
