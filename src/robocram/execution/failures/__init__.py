"""Plan failures by area, importable by their CRAM names in CamelCase.

``PlanFailure`` is the root; ``LowLevelFailure`` and ``HighLevelFailure`` group CRAM's
taxonomy; ``failure_class("torso-goal-not-reached")`` finds a class by its CRAM name.
``SetupFailure`` roots the errors of plans and modules used wrongly (``PlanSetupError``,
``ProjectionError``). ``NotInTopLevel`` and ``RetryOutsideHandler`` are errors of the plan
language's own use, raised outside any handler's reach, so they are not plan failures.
"""

from robocram.execution.failures.environment import (
    EnvironmentManipulationImpossible,
    EnvironmentUnreachable,
)
from robocram.execution.failures.executive import (
    DesignatorFailure,
    DesignatorGoalParsingFailure,
    DesignatorReferenceFailure,
    NoMatchingProcessModule,
    ProcessModuleFailure,
    ProcessModuleInputError,
)
from robocram.execution.failures.failure_line import failure_line
from robocram.execution.failures.flying import (
    FlyingGoalInCollision,
    FlyingGoalNotReached,
    FlyingLowLevelFailure,
)
from robocram.execution.failures.high_level import HighLevelFailure
from robocram.execution.failures.low_level import ActionlibActionTimedOut, LowLevelFailure
from robocram.execution.failures.manipulation import (
    GripperClosedCompletely,
    GripperGoalNotReached,
    GripperLowLevelFailure,
    GripperMetOneSide,
    GripperPathBlocked,
    ManipulationGoalInCollision,
    ManipulationGoalNotReached,
    ManipulationLowLevelFailure,
    ManipulationPathBlocked,
    ManipulationPoseUnreachable,
    ObjectUndeliverable,
    ObjectUnfetchable,
    ObjectUnreachable,
    ToolPathUnreachable,
)
from robocram.execution.failures.navigation import (
    NavigationGoalInCollision,
    NavigationGoalNotReached,
    NavigationGoalOutsideArea,
    NavigationLowLevelFailure,
    NavigationPathBlocked,
    NavigationPoseUnreachable,
)
from robocram.execution.failures.perception import (
    LookingHighLevelFailure,
    ObjectNowhereToBeFound,
    PerceptionBlockedByRobot,
    PerceptionLowLevelFailure,
    PerceptionObjectNotFound,
    PtuGoalNotReached,
    PtuGoalUnreachable,
    PtuLowLevelFailure,
    PtuPathBlocked,
)
from robocram.execution.failures.plan_failure import PlanFailure, failure_class
from robocram.execution.failures.plan_language import (
    CompositeFailure,
    FluentWaitTimeout,
    NotInTopLevel,
    RetryOutsideHandler,
)
from robocram.execution.failures.setup import SetupFailure
from robocram.execution.failures.torso import (
    TorsoGoalNotReached,
    TorsoGoalUnreachable,
    TorsoLowLevelFailure,
    TorsoPathBlocked,
)

__all__ = [
    "ActionlibActionTimedOut",
    "CompositeFailure",
    "DesignatorFailure",
    "DesignatorGoalParsingFailure",
    "DesignatorReferenceFailure",
    "EnvironmentManipulationImpossible",
    "EnvironmentUnreachable",
    "FluentWaitTimeout",
    "FlyingGoalInCollision",
    "FlyingGoalNotReached",
    "FlyingLowLevelFailure",
    "GripperClosedCompletely",
    "GripperMetOneSide",
    "GripperGoalNotReached",
    "GripperLowLevelFailure",
    "GripperPathBlocked",
    "HighLevelFailure",
    "LookingHighLevelFailure",
    "LowLevelFailure",
    "ManipulationGoalInCollision",
    "ManipulationGoalNotReached",
    "ManipulationLowLevelFailure",
    "ManipulationPathBlocked",
    "ManipulationPoseUnreachable",
    "ToolPathUnreachable",
    "NavigationGoalInCollision",
    "NavigationGoalNotReached",
    "NavigationGoalOutsideArea",
    "NavigationLowLevelFailure",
    "NavigationPathBlocked",
    "NavigationPoseUnreachable",
    "NoMatchingProcessModule",
    "NotInTopLevel",
    "ObjectNowhereToBeFound",
    "ObjectUndeliverable",
    "ObjectUnfetchable",
    "ObjectUnreachable",
    "PerceptionLowLevelFailure",
    "PerceptionBlockedByRobot",
    "PerceptionObjectNotFound",
    "PlanFailure",
    "ProcessModuleFailure",
    "ProcessModuleInputError",
    "PtuGoalNotReached",
    "PtuGoalUnreachable",
    "PtuLowLevelFailure",
    "PtuPathBlocked",
    "RetryOutsideHandler",
    "SetupFailure",
    "TorsoGoalNotReached",
    "TorsoGoalUnreachable",
    "TorsoLowLevelFailure",
    "TorsoPathBlocked",
    "failure_class",
    "failure_line",
]
