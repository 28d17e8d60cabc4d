"""Errors of batch projection: one root, subclasses that name the culprit and the fix."""

from __future__ import annotations


class BatchError(Exception):
    """Root of every error raised by :mod:`robocram.batch`."""


class BadVariant(BatchError):
    """A variant cannot be run as given (the field and what to write instead)."""

    def __init__(self, field: str, value: object, fix: str) -> None:
        super().__init__(f"variant {field}={value!r}: {fix}")
        self.field = field
        self.value = value


class UnknownBackend(BatchError):
    """``backend`` names no batch backend."""

    def __init__(self, backend: str, known: tuple[str, ...]) -> None:
        super().__init__(f"no batch backend {backend!r}; use one of {', '.join(known)}")
        self.backend = backend


class BackendMissing(BatchError):
    """The backend's optional package is not installed (the message says how to install it)."""

    def __init__(self, package: str, install: str) -> None:
        super().__init__(f"the batch backend needs {package!r}: {install}")
        self.package = package


class BadSpec(BatchError):
    """A batch spec file cannot be used as written (the file, the key and the fix)."""

    def __init__(self, path: object, key: str, value: object, fix: str) -> None:
        super().__init__(f"batch spec {path}: {key}={value!r}: {fix}")
        self.path = path
        self.key = key
        self.value = value


class UnguardedBatch(BatchError):
    """A script starts a process batch at its top level, outside ``if __name__ ==
    "__main__":``: each spawned worker imports the script and would start the batch again."""

    def __init__(self, script: str, line: int) -> None:
        super().__init__(
            f"{script}, line {line}: the batch starts at the script's top level; spawned "
            "workers import the script and would start it again (every variant LOST). Put "
            'it under `if __name__ == "__main__":`, or pass backend="ray"'
        )
        self.script = script
        self.line = line
