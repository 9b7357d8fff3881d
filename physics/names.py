"""Unique names of a world's items (bodies, springs, ...): name <-> stable id, validated."""
from __future__ import annotations

from .validate import shown, text


class Names:
    """A two-way map between the names and the stable ids of one kind of item."""

    def __init__(self, what: str):
        self.what = what            # "body", "spring", ... for messages
        self.ids: dict[str, int] = {}
        self.names: dict[int, str] = {}

    def check_new(self, name) -> None:
        """ValueError naming ``name`` unless it is a non-empty string (valid Unicode: it is saved
        in scene files) that no item has yet."""
        if not isinstance(name, str) or not name:
            raise ValueError(f"name: a {self.what} name must be a non-empty string, got {shown(name)}")
        text(name, "name")
        if name in self.ids:
            raise ValueError(f"name: a {self.what} named {shown(name)} already exists")

    def add(self, oid: int, name) -> None:
        if name is not None:
            self.ids[name] = oid
            self.names[oid] = name

    def drop(self, oid: int) -> None:
        nm = self.names.pop(oid, None)
        if nm is not None:
            del self.ids[nm]

    def rename(self, oid: int, name) -> None:
        old = self.names.get(oid)
        if name == old:
            return
        if name is not None:
            self.check_new(name)
        self.drop(oid)
        self.add(oid, name)

    def id_of(self, name: str) -> int:
        """The id of ``name``; KeyError naming it if there is none."""
        try:
            return self.ids[name]
        except (KeyError, TypeError):
            raise KeyError(f"no {self.what} named {shown(name)}") from None

    def name_of(self, oid: int):
        return self.names.get(oid)
