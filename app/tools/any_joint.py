"""Joint tool: any kind the core declares (physics/joint_params.py), chosen in the Tools panel,
made from the bodies under the pointer.  What the gesture gives follows the kind's declared
geometry: a kind held at one point (``anchor``) takes the press point; one held at two
(``anchor_a``/``anchor_b``) needs a drag, from body_a to body_b's point (or the background); a
kind with an axis takes the drag's direction as its axis (a click: its default axis).  Every
parameter starts at its declared default and is edited in the inspector, which selects the new
joint (a motor joint's targets: where body_a is now).  The dedicated tools (hinge, slider, rope, ...) remain the quick ways to the common kinds."""
from __future__ import annotations

import numpy as np

from physics import joint_params as jp

from ..picking import bodies_at
from .base import PREVIEW
from .joining import DragJointTool, add_joint

#: the kinds this tool offers: every declared kind but the pointer's own drag
KINDS = tuple(k for k in jp.KINDS if k != "mouse")


def held_pose(a, b) -> dict:
    """A motor joint's targets that hold ``a`` where it is relative to ``b`` (the world: None):
    its origin in b's frame and its angle relative to b's.  The declared defaults (a's origin on
    b's, the same angle) would pull the bodies together the moment the scene plays."""
    qb = 0.0 if b is None else b.angle
    d = np.subtract(a.position, (0.0, 0.0) if b is None else b.position)
    c, s = np.cos(qb), np.sin(qb)
    return {"linear_offset": (float(c * d[0] + s * d[1]), float(-s * d[0] + c * d[1])),
            "angular_offset": float(a.angle - qb)}


class JointTool(DragJointTool):
    name = "joint"
    verb = "join"

    @property
    def kind(self) -> str:
        return self.editor.tool_options.joint_kind

    @property
    def help(self) -> str:
        two = "anchor_a" in jp.GEOMETRY[self.kind]
        how = "drag from a body to the other end's point" if two else "click over one or two bodies (or drag)"
        return f"{self.kind}: {jp.KINDS[self.kind].doc}; {how}"

    def clicked(self, a, b, p0):
        self.finish(a, b, p0, None)

    def finish(self, a, b, p0, p1):
        """The joint from the press point ``p0`` and the release point ``p1`` (None: a click, or a
        drag shorter than MIN_PX pixels)."""
        kind, geometry = self.kind, jp.GEOMETRY[self.kind]
        fields = {}
        if "anchor_a" in geometry:
            if p1 is None:
                self.editor.hint(f"drag to make a {kind} joint: from a body to where its other end holds",
                                 error=False)
                return
            under = [x for x in bodies_at(self.editor.world, p1) if x is not a]
            b = under[0] if under else None
            fields.update(anchor_a=tuple(map(float, p0)), anchor_b=tuple(map(float, p1)))
        elif "anchor" in geometry:
            fields["anchor"] = tuple(map(float, p0))
        if "axis" in geometry and p1 is not None:
            d = p1 - p0
            fields["axis"] = tuple(map(float, d / np.hypot(*d)))
        if a.kind == "static" and (b is None or b.kind == "static"):
            self.editor.hint("nothing to join: the bodies here are static (they do not move)")
            return
        if "linear_offset" in jp.PARAMS[kind]:
            fields.update(held_pose(a, b))
        add_joint(self.editor, kind, a, b, **fields)

    def decorate(self, decor, cursor):
        if self.start is not None and self.start[0].alive:
            p0 = self.start[2]
            decor.segments.append((p0, cursor, 2.0, PREVIEW))
            decor.points.append((p0, 4.0, PREVIEW))
