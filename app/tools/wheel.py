"""Wheel tool: click a circle over a body: a wheel joint at the circle's centre, the body under it
the chassis, the suspension along the chassis' up direction (frequency and damping ratio from the
tool options)."""
from __future__ import annotations

import math

import physics

from ..picking import bodies_at
from .base import Tool
from .joining import add_joint


class WheelTool(Tool):
    name = "wheel"
    snaps = False
    help = "click where a circle lies over a body: the circle becomes its wheel, on a sprung axle"

    def press(self, p, button, mods):
        ed = self.editor
        under = bodies_at(ed.world, p)
        wheels = [b for b in under if isinstance(b.shape, physics.Circle)]
        if not wheels:
            ed.hint("click a circle (the wheel) where it lies over a body (the chassis)")
            return
        wheel = wheels[0]
        chassis = [b for b in under if b is not wheel]
        if not chassis:
            ed.hint("the circle must lie over a body: the chassis it turns on")
            return
        car = chassis[0]
        q = car.angle           # the suspension travels along the chassis' own up direction
        o = ed.tool_options
        add_joint(ed, "wheel", car, wheel, anchor=tuple(map(float, wheel.center_of_mass)),
                  axis=(-math.sin(q), math.cos(q)), spring_hertz=o.wheel_hertz,
                  spring_damping_ratio=o.wheel_damping_ratio)
