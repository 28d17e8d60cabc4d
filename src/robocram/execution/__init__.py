"""The executive: tasks, the plan language, failures, failure handling and fluents.

Plans are Python functions run under ``top_level``; plan forms (``seq``, ``par``,
``pursue``, ``try_all``, ``try_in_order``, ``partial_order``, ``with_tags``) take thunks
and build the task tree as they run. Stopping is cooperative at stop points
(``checkpoint``, ``sleep``, fluent waits, PERFORM). Failure classes live in
``robocram.execution.failures``.
"""

from robocram.execution.environment import Environment
from robocram.execution.failure_handling import (
    FailureControl,
    RetryCounter,
    failure_handled,
    retry,
    with_failure_handling,
)
from robocram.execution.failures import NotInTopLevel, PlanFailure
from robocram.execution.fluent import Fluent, derive, fl_and, fl_not, fl_or
from robocram.execution.motion_process_module import (
    MotionProcessModule,
    matching_facts,
    module_atom,
    motion_types_of,
)
from robocram.execution.par import par
from robocram.execution.partial_order import partial_order
from robocram.execution.perform import perform, perform_plan, register_plan
from robocram.execution.process_module import ProcessModule
from robocram.execution.process_module_matching import (
    install_process_module_interface,
    matching_process_modules,
    process_modules_running,
    running_process_modules,
)
from robocram.execution.pursue import pursue
from robocram.execution.seq import seq
from robocram.execution.tags import tag, tagged, with_tags
from robocram.execution.task import Task, TaskStatus, TaskStopped
from robocram.execution.task_context import checkpoint, current_task, sleep, sub_task
from robocram.execution.task_listeners import TaskListener, listening, task_listeners
from robocram.execution.task_snapshot import STATUS_MARKS, TaskSnapshot
from robocram.execution.task_tree import TaskTree
from robocram.execution.top_level import TopLevel, run_top_level, top_level
from robocram.execution.try_forms import try_all, try_in_order
from robocram.execution.whenever import whenever

__all__ = [
    "STATUS_MARKS",
    "Environment",
    "FailureControl",
    "Fluent",
    "MotionProcessModule",
    "NotInTopLevel",
    "PlanFailure",
    "ProcessModule",
    "RetryCounter",
    "Task",
    "TaskSnapshot",
    "TaskStatus",
    "TaskListener",
    "TaskStopped",
    "TaskTree",
    "TopLevel",
    "checkpoint",
    "current_task",
    "derive",
    "failure_handled",
    "fl_and",
    "fl_not",
    "fl_or",
    "install_process_module_interface",
    "listening",
    "matching_facts",
    "matching_process_modules",
    "module_atom",
    "motion_types_of",
    "par",
    "partial_order",
    "perform",
    "perform_plan",
    "process_modules_running",
    "pursue",
    "register_plan",
    "retry",
    "run_top_level",
    "running_process_modules",
    "seq",
    "sleep",
    "sub_task",
    "tag",
    "tagged",
    "task_listeners",
    "top_level",
    "try_all",
    "try_in_order",
    "whenever",
    "with_failure_handling",
    "with_tags",
]
