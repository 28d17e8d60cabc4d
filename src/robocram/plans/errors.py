"""Errors of robot-independent plans: setup mistakes and stages that ran out of retries."""

from __future__ import annotations

from robocram.execution.failures import (
    ObjectUndeliverable,
    ObjectUnfetchable,
    PerceptionObjectNotFound,
    SetupFailure,
)


class PlanSetupError(SetupFailure, RuntimeError):
    """A plan needs knowledge the current environment does not give (no robot, say)."""


class SearchExhausted(PerceptionObjectNotFound):
    """Every candidate place was looked at and the object was in none of them."""

    searched: tuple[str, ...] | None = None  # the places looked at, in order
    occluded_by: tuple[str, ...] | None = None  # what hid a place or the object, most first
    hint = "put the object's usual place into the KB (usual_location/3) or search elsewhere"


class FetchExhausted(ObjectUnfetchable):
    """Every stand tried (within the retry bound) failed to pick the object up."""

    causes: tuple[Exception, ...] | None = None  # one failure per attempt, in order
    attempts: int | None = None  # stands where picking up was tried
    blocked_by: tuple[str, ...] | None = None  # what the robot touched at the stands refused
    occluded_by: tuple[str, ...] | None = None  # what hid the object from the stands refused
    hint = "raise stand_retries, give another arm or grasp, or clear the object's surroundings"


class DeliveryExhausted(ObjectUndeliverable):
    """Every placing spot and stand tried (within the retry bounds) failed to place it."""

    causes: tuple[Exception, ...] | None = None  # one failure per attempt, in order
    attempts: int | None = None  # stands tried
    hint = "give a target the robot can stand beside, or raise place_retries / stand_retries"


class ObjectLetGo(ObjectUndeliverable):
    """The hand let the object go before it was delivered (a put let it go, then failed):
    no other stand or spot can put down what the hand no longer holds."""

    object_name: str | None = None
    causes: tuple[Exception, ...] | None = None  # the failures met, the let-go's last
    hint = "fetch it again from where it lies"


class PlanArgumentError(ValueError):
    """A value given to a plan is outside what it accepts."""

    summary = "a value given to a plan is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"
