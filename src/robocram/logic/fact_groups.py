"""Loading a fact group as one atomic edit of a knowledge base's predicates.

The edit works on copies (copy-on-write: a new predicate table, and a new `Pred` for every
predicate it touches), and the knowledge base installs the result in one assignment. A
query already running keeps the table it started with, so it sees the old group or the
new one, never half of each; a load that fails (a clause of another group's predicate, a
built-in redefined, a failing directive) leaves the knowledge base as it was.

Library predicates (written in Prolog, owned by `LIBRARY_OWNER`) give way to a user
definition: the group's clauses replace them, as in SWI-Prolog and CRAM. Built-ins stay
protected.
"""

from __future__ import annotations

from collections.abc import Iterable

from robocram.logic.clause import Clause
from robocram.logic.errors import FactGroupError, PrologPermissionError
from robocram.logic.predicate import USER, Key, Pred
from robocram.logic.terms import Term

__all__ = ["LIBRARY_OWNER", "Groups", "GroupEdit", "refuse_system"]

LIBRARY_OWNER = "library"
Groups = dict[str, tuple[set[Key], set[Key]]]  # group -> (its predicates, its extendables)


def refuse_system(pred: Pred) -> PrologPermissionError:
    """The error for an attempt to define clauses for a built-in."""
    return PrologPermissionError(
        "modify",
        "static_procedure",
        Term("/", (pred.name, pred.arity)),
        f"{pred.indicator} is a built-in predicate and cannot be redefined; choose another name",
    )


class GroupEdit:
    """A staged copy of the predicate table and groups; read `preds`/`groups` to commit."""

    def __init__(self, preds: dict[Key, Pred], groups: Groups) -> None:
        self._original = preds
        self.preds = dict(preds)
        self.groups: Groups = {g: (set(k), set(e)) for g, (k, e) in groups.items()}
        self._copied: set[Key] = set()

    def load(
        self,
        name: str,
        replace: bool,
        clauses: list[tuple[Key, Clause]],
        shared: set[Key],
        dynamic: Iterable[Key] = (),
    ) -> None:
        """Stage fact group `name`: drop its old clauses if `replace`, then add `clauses`."""
        if replace:
            self.drop_group(name)
        keys, ext = self.groups.setdefault(name, (set(), set()))
        ext.update(shared)
        self.declare_interface(shared, name)
        for key in dynamic:
            self.user_pred(key).dynamic = True
        for key, _ in clauses:
            self.check_owner(key, name)
        for key, clause in clauses:
            pred = self.user_pred(key)
            if pred.owner is None:
                pred.owner = name
            pred.add_last(clause)
            keys.add(key)

    def keep_unchanged(self) -> bool:
        """Put back the original of every copied predicate that ended up the same.

        True when all of them did: the edit changed no predicate. A kept predicate keeps
        its compiled procedure, which a copy would build again.
        """
        same = True
        for key in self._copied:
            new = self.preds.get(key)
            old = self._original.get(key)
            if new is not None and old is not None and _same_definition(old, new):
                self.preds[key] = old
            else:
                same = False
        return same

    def writable(self, key: Key) -> Pred | None:
        """This edit's own copy of the predicate `key` (None when there is none)."""
        pred = self.preds.get(key)
        if pred is None or key in self._copied or pred.system:
            return pred
        pred = self.preds[key] = pred.copy()
        self._copied.add(key)
        return pred

    def user_pred(self, key: Key) -> Pred:
        """The user predicate `key`, created (or taken over from the library) if needed."""
        pred = self.writable(key)
        if pred is None or pred.owner == LIBRARY_OWNER:
            pred = self.preds[key] = Pred(key[0], key[1])
            self._copied.add(key)
        elif pred.system or pred.kind != USER:
            raise refuse_system(pred)
        return pred

    def drop_group(self, name: str) -> None:
        """Remove the clauses of group `name`."""
        keys, _ = self.groups.pop(name, (set(), set()))
        for key in keys:
            pred = self.writable(key)
            if pred is None:
                continue
            pred.set_clauses([c for c in pred.live(pred.clauses) if c.group != name])
            if pred.owner == name:
                others = [c.group for c in pred.clauses if c.group is not None]
                pred.owner = others[0] if others else None

    def declare_interface(self, keys: set[Key], group: str) -> None:
        """A group that lists a predicate as extendable declares it (CRAM's interface idiom).

        The predicate then exists (a call fails instead of raising "unknown predicate") and
        the declaring group owns it, so any number of other groups may add clauses.
        """
        for key in keys:
            pred = self.preds.get(key)
            if pred is not None and pred.kind != USER:
                continue  # a Python predicate or built-in: nothing to declare
            pred = self.user_pred(key)
            if pred.owner is None or not pred.clauses:
                pred.owner = group

    def check_owner(self, key: Key, group: str) -> None:
        """Refuse clauses for a built-in, or for another group's unshared predicate."""
        pred = self.preds.get(key)
        if pred is None or pred.owner == LIBRARY_OWNER:
            return
        if pred.system:
            raise refuse_system(pred)
        if pred.owner is None or pred.owner == group:
            return
        owner_ext = self.groups.get(pred.owner, (set(), set()))[1]
        mine = self.groups.get(group, (set(), set()))[1]
        if key not in owner_ext and key not in mine:
            raise FactGroupError(pred.indicator, pred.owner, group)


def _same_definition(old: Pred, new: Pred) -> bool:
    """Whether two versions of a predicate hold the same clause objects and settings."""
    if old.erased or new.erased:
        return False
    a, b = old.clauses, new.clauses
    return (
        len(a) == len(b)
        and all(x is y for x, y in zip(a, b, strict=True))
        and (old.kind, old.dynamic, old.owner, old.extendable)
        == (new.kind, new.dynamic, new.owner, new.extendable)
        and old.fn is new.fn
        and old.pyfn is new.pyfn
    )
