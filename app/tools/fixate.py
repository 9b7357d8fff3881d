"""Fixate tool: a click welds the two topmost bodies under the pointer together (a rigid weld
joint at that point), or a body alone to the background."""
from __future__ import annotations

from .joining import ClickJointTool


class FixateTool(ClickJointTool):
    name = "fixate"
    kind = "weld"
    verb = "fixate"
    help = "click over two bodies: weld them together (over one body: fix it to the background)"

    def fields(self, a, b, p):
        return {"anchor": p}
