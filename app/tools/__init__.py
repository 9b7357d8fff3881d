"""The sandbox's mouse tools, one per module.  ``TOOLS`` is their order in the Tools panel and
their keys (1, 2, ... for the first nine).  To add a tool: write a :class:`Tool` subclass in its
own module and append it here (docs/sandbox.md, "Adding a tool")."""
from .any_joint import JointTool
from .base import Tool, ToolOptions, body_args
from .box import BoxTool
from .capsule import CapsuleTool
from .circle import CircleTool
from .fixate import FixateTool
from .ground import GroundTool
from .hinge import HingeTool
from .laser import LaserTool
from .motor import MotorTool
from .ngon import NgonTool
from .polygon import PolygonTool
from .rope import RopeTool
from .select import SelectTool
from .sketch import SketchTool
from .slider import SliderTool
from .spring import SpringTool
from .tracer import TracerTool
from .wheel import WheelTool

TOOLS = (SelectTool, BoxTool, PolygonTool, NgonTool, CircleTool, SpringTool, TracerTool, HingeTool, MotorTool,
         FixateTool, SliderTool, RopeTool, WheelTool, SketchTool, CapsuleTool, GroundTool,
         LaserTool, JointTool)

__all__ = ["TOOLS", "Tool", "ToolOptions", "body_args"]
