"""Motor tool: a hinge with a motor (speed and torque from the tool options), made like the
hinge: over two bodies it joins the two topmost, over one it pins the body to the background."""
from __future__ import annotations

from .joining import ClickJointTool


class MotorTool(ClickJointTool):
    name = "motor"
    kind = "revolute"
    verb = "motorise"
    help = "click over two bodies: a motor hinge (over one body: to the background); speed and torque " \
           "in the options below"

    def fields(self, a, b, p):
        o = self.editor.tool_options
        return {"anchor": p, "motor_speed": o.motor_speed, "max_motor_torque": o.motor_torque}
