"""Hinge tool: a click joins the two topmost bodies under the pointer with a revolute joint at
that point; over one body it pins the body to the background there."""
from __future__ import annotations

from .joining import ClickJointTool


class HingeTool(ClickJointTool):
    name = "hinge"
    kind = "revolute"
    verb = "hinge"
    help = "click over two bodies: hinge them there (over one body: pin it to the background)"

    def fields(self, a, b, p):
        return {"anchor": p}
