# The project's two commands: `make demo` (set up .venv, install, run the demo) and `make test`.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
ROS_STAMP := $(VENV)/.ros_installed
ROS_DEFINITIONS := $(wildcard src/robocram/ros/definitions/*/*/*)
ROS2_STAMP := $(VENV)/.ros2_installed
ROS2_DEFINITIONS := $(wildcard src/robocram/ros/definitions2/*/*/* src/robocram/ros/definitions2/*/*.*)

.PHONY: demo test setup installed lint typecheck unit bench clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PY) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	bash tools/setup_chromium.sh
	touch $(STAMP)

# A venv whose editable install points at another checkout (a moved or copied tree, a git
# worktree that shared it) would test that other tree: reinstall it from this one.
installed: $(STAMP)
	@$(BIN)/python -c "import pathlib, robocram; raise SystemExit(pathlib.Path(robocram.__file__).resolve().parents[1] != pathlib.Path('src').resolve())" 2>/dev/null \
		|| $(BIN)/python -m pip install --quiet -e '.[dev]'

# robocram.ros: ROS 1 from Debian, generated control_msgs, a .pth into the venv
$(ROS_STAMP): $(STAMP) tools/setup_ros.sh tools/generate_ros_messages.py $(ROS_DEFINITIONS)
	bash tools/setup_ros.sh $(VENV)
	touch $(ROS_STAMP)

# robocram.ros with ROS 2: Jazzy's wheels and generated interfaces in $(VENV)/ros2, a prefix
# of its own (ROS 1's and ROS 2's messages share package names; docs/architecture.md)
$(ROS2_STAMP): $(STAMP) tools/setup_ros2.sh tools/ros2_cmake_fix.cmake $(ROS2_DEFINITIONS)
	bash tools/setup_ros2.sh $(VENV)
	touch $(ROS2_STAMP)

setup: $(STAMP) $(ROS_STAMP) $(ROS2_STAMP)

# `make demo ROBOT=path/to/my_robot.py` runs the kitchen demo on a description file;
# `make demo ROBOT=... DEMO_ARGS="--stand-retries 10"` passes options on
ROBOT ?= pr2
DEMO_ARGS ?=
demo: installed
	$(BIN)/python -m robocram.demo --robot $(ROBOT) $(DEMO_ARGS)
	@echo "the robocram command: 'source $(BIN)/activate' then 'robocram --help', or '$(BIN)/robocram --help'"

lint: installed
	$(BIN)/ruff check src tests benchmarks examples tools
	$(BIN)/ruff format --check src tests benchmarks examples tools

typecheck: installed $(ROS_STAMP) $(ROS2_STAMP)
	$(BIN)/mypy

# --no-loadscope-reorder: xdist deals the groups and tests out in the order tests/conftest.py
# gives them, longest first (tests/suite_durations.json), so no long one is left for the end.
# WORKERS: xdist's -n (auto: one per core; three on two cores were no faster, session 26).
# Bytecode is written and read (PYTHONDONTWRITEBYTECODE emptied, if the environment set it):
# the suite starts many interpreters (xdist's workers, the batch's processes and Ray actors,
# ROS drivers, CLI runs), and without it each compiled robocram from source (up to 0.6 s) and
# each worker rewrote every test module's asserts again (8 s of its 13 s collection).
# compileall writes src's bytecode on both cores first; the tests' is written by the first run.
WORKERS ?= auto
unit: installed $(ROS_STAMP) $(ROS2_STAMP)
	PYTHONDONTWRITEBYTECODE= $(BIN)/python -m compileall -q -j 0 src
	PYTHONDONTWRITEBYTECODE= $(BIN)/pytest -n $(WORKERS) --dist loadgroup --no-loadscope-reorder --durations=15

# mypy (one core, half a minute or more without its cache) runs beside the tests: they leave
# a core idle while ROS and the viewer wait for messages and pages. The set-up is made first,
# one step at a time: two installs into one venv at once could clash.
test: lint $(ROS_STAMP) $(ROS2_STAMP)
	$(MAKE) --no-print-directory -j2 typecheck unit

bench: installed
	for f in benchmarks/*_bench.py; do $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(VENV) build src/*.egg-info .pytest_cache .mypy_cache .ruff_cache
