# The project's two commands: `make demo` (set up .venv, install, run the demo) and `make test`.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
ROS_STAMP := $(VENV)/.ros_installed
ROS_DEFINITIONS := $(wildcard src/robocram/ros/definitions/*/*/*)

.PHONY: demo test setup lint typecheck unit bench clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PY) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	bash tools/setup_chromium.sh
	touch $(STAMP)

# robocram.ros: ROS 1 from Debian, generated control_msgs, a .pth into the venv
$(ROS_STAMP): $(STAMP) tools/setup_ros.sh tools/generate_ros_messages.py $(ROS_DEFINITIONS)
	bash tools/setup_ros.sh $(VENV)
	touch $(ROS_STAMP)

setup: $(STAMP) $(ROS_STAMP)

demo: $(STAMP)
	$(BIN)/python -m robocram.demo

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks examples tools
	$(BIN)/ruff format --check src tests benchmarks examples tools

typecheck: $(STAMP) $(ROS_STAMP)
	$(BIN)/mypy

unit: $(STAMP) $(ROS_STAMP)
	$(BIN)/pytest

test: lint typecheck unit

bench: $(STAMP)
	for f in benchmarks/*_bench.py; do $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(VENV) build src/*.egg-info .pytest_cache .mypy_cache .ruff_cache
