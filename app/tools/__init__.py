"""The sandbox's mouse tools, one per module.  ``TOOLS`` is their order in the Tools panel and
their keys (1, 2, ...).  To add a tool: write a :class:`Tool` subclass in its own module and
append it here (docs/sandbox.md, "Adding a tool")."""
from .base import Tool, ToolOptions, body_args
from .box import BoxTool
from .circle import CircleTool
from .ngon import NgonTool
from .polygon import PolygonTool
from .select import SelectTool
from .spring import SpringTool
from .tracer import TracerTool

TOOLS = (SelectTool, BoxTool, PolygonTool, NgonTool, CircleTool, SpringTool, TracerTool)

__all__ = ["TOOLS", "Tool", "ToolOptions", "body_args"]
