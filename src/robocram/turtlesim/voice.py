"""A robot with no body at all, for human-robot interaction: it says and it listens.

Motions are not only for manipulators: ``a.motion(type="saying", text="hello")`` grounds
to ``say(Text)`` and ``a.motion(type="listening")`` to ``listen(Timeout)``; the voice
process module writes to a transcript and reads what the human said from a queue.
"""

from __future__ import annotations

import queue
from typing import Any

from robocram.execution.environment import Environment
from robocram.execution.failures import PlanFailure
from robocram.execution.process_module import ProcessModule
from robocram.execution.task_context import checkpoint
from robocram.logic import Term

VOICE_FACTS = """
motion_grounding(D, say(Text)) :-
    motion_desig(D), desig_prop(D, type, saying), desig_prop(D, text, Text).
motion_grounding(D, listen(Timeout)) :-
    motion_desig(D), desig_prop(D, type, listening), voice_timeout(D, Timeout).
voice_timeout(D, Timeout) :- desig_prop(D, timeout, Timeout), !.
voice_timeout(_, 5.0).
matching_process_module(D, voice) :- desig_prop(D, type, saying).
matching_process_module(D, voice) :- desig_prop(D, type, listening).
available_process_module(voice).
"""
_POLL = 0.05  # [s] how often a listening robot checks whether it was stopped


class NothingHeard(PlanFailure):
    """The robot listened and nobody spoke within the timeout."""

    timeout: float | None = None
    summary = "nothing was heard"
    hint = "ask again, or listen longer"


class VoicePM(ProcessModule):
    """Owns the robot's voice: ``say`` appends to ``transcript``, ``listen`` reads ``heard``."""

    name = "voice"

    def __init__(self) -> None:
        super().__init__()
        self.transcript: list[str] = []
        self._heard: queue.Queue[str] = queue.Queue()

    def hear(self, text: str) -> None:
        """Let the human say ``text`` to the robot."""
        self._heard.put(text)

    def execute(self, command: object) -> Any:
        """Say a text or listen for one."""
        if isinstance(command, Term) and command.name == "say" and command.arity == 1:
            self.transcript.append(str(command.args[0]))
            return None
        if isinstance(command, Term) and command.name == "listen" and command.arity == 1:
            return self._listen(float(command.args[0]))
        raise self.unsupported(command, ["say/1", "listen/1"])

    def _listen(self, timeout: float) -> str:
        waited = 0.0
        while waited < timeout:
            checkpoint()
            try:
                return self._heard.get(timeout=min(_POLL, timeout - waited))
            except queue.Empty:
                waited += _POLL
        raise NothingHeard(f"nothing was heard within {timeout} s", timeout=timeout)


def voice_environment(voice: VoicePM | None = None) -> Environment:
    """Return the bodiless robot's environment (its voice module is ``env.module('voice')``)."""
    return Environment("voice_robot", process_modules=(voice or VoicePM(),), facts=VOICE_FACTS)
