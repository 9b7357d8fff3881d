"""Bodies' own fill colours: app data kept by the editor (Ref -> (r, g, b) in [0, 1]), undoable
edits, and the scene file's ``bodies[i].color`` ("#rrggbb"), which the loader leaves in
``world.metadata["colors"]`` (body id -> hex) so the physics core never sees a colour."""
from __future__ import annotations

import time

from .commands import Command


def hex_to_rgb(hexstr: str) -> tuple:
    """"#rrggbb" -> (r, g, b) in [0, 1]."""
    h = hexstr.lstrip("#")
    return tuple(int(h[i:i + 2], 16) / 255.0 for i in (0, 2, 4))


def rgb_to_hex(rgb) -> str:
    """(r, g, b) in [0, 1] -> "#rrggbb" (the scene file's form)."""
    return "#" + "".join(f"{min(255, max(0, round(float(v) * 255))):02x}" for v in rgb)


def checked_rgb(rgb):
    """(r, g, b) floats, or ValueError naming the field."""
    rgb = tuple(float(v) for v in rgb)
    if len(rgb) != 3 or not all(0.0 <= v <= 1.0 for v in rgb):
        raise ValueError(f"colour: three components in [0, 1], got {rgb!r}")
    return rgb


def from_metadata(world, refs) -> dict:
    """{Ref: rgb} of the colours a loaded scene gave its bodies."""
    by_id = {b.id: b for b in world.bodies}
    return {refs.of(by_id[i]): hex_to_rgb(h) for i, h in world.metadata.get("colors", {}).items() if i in by_id}


def to_metadata(world, colors: dict) -> None:
    """Put the editor's colours where the scene saver reads them (by the bodies' current ids:
    a body brought back by undo has a new one)."""
    out = {r.obj.id: rgb_to_hex(c) for r, c in colors.items() if r.obj is not None and r.obj.alive}
    if out:
        world.metadata["colors"] = out
    else:
        world.metadata.pop("colors", None)


class SetColor(Command):
    """A body's own colour (None: the default palette's again). Drags of the colour editor
    within 1.5 s merge into one step."""

    def __init__(self, app, body, rgb):
        self.ref = app.refs.of(body)
        self.new = rgb
        self.old = app.colors.get(self.ref)
        self.t = time.monotonic()
        self.label = "set colour"

    @staticmethod
    def apply(app, ref, rgb):
        if rgb is None:
            app.colors.pop(ref, None)
        else:
            app.colors[ref] = rgb

    def do(self, app):
        self.apply(app, self.ref, self.new)

    def undo(self, app):
        self.apply(app, self.ref, self.old)

    def merge(self, other) -> bool:
        if isinstance(other, SetColor) and other.ref is self.ref and other.t - self.t < 1.5:
            self.new, self.t = other.new, other.t
            return True
        return False
