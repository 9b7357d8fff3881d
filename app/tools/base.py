"""What every mouse tool shares: the Tool interface, the palette options and body defaults.

A tool receives the :class:`app.editor.Editor` (world, selection, commands, camera) and turns
pointer events in world coordinates into commands.  See docs/sandbox.md, "Adding a tool".
"""
from __future__ import annotations

PREVIEW = (1.0, 1.0, 1.0, 0.85)
PREVIEW_DIM = (1.0, 1.0, 1.0, 0.35)
JOINT = (1.0, 0.85, 0.35, 0.95)


class ToolOptions:
    """Palette parameters shared by the creation tools (sizes in metres, stiffness in N/m)."""

    def __init__(self):
        self.kind = "dynamic"
        self.sides = 6
        self.default_size = 1.0
        self.density = 1.0
        self.friction = 0.6
        self.restitution = 0.1
        self.spring_stiffness = 60.0
        self.spring_damping = 1.0
        self.joint_hertz = 4.0           # the mouse drag's joint
        self.joint_damping_ratio = 0.7
        self.motor_speed = 2.0           # motor tool (rad/s, counter-clockwise) and its torque (N m)
        self.motor_torque = 50.0
        self.wheel_hertz = 4.0           # wheel tool: suspension frequency (Hz) and damping ratio
        self.wheel_damping_ratio = 0.7
        self.slider_limits = True        # slider tool: the dragged segment is the travel
        self.capsule_radius = 0.25       # capsule tool: the radius (m) of a dragged capsule
        self.joint_kind = "rotary"       # joint tool: the kind it makes (any declared kind)


def body_args(opts: ToolOptions, position, angle=0.0) -> dict:
    """``World.add_body`` keyword arguments for a new body at ``position`` (m) from the palette."""
    return {"kind": opts.kind, "position": tuple(map(float, position)), "angle": angle,
            "velocity": (0.0, 0.0), "angular_velocity": 0.0, "density": opts.density,
            "restitution": opts.restitution, "friction": (opts.friction, opts.friction), "name": None}


class Tool:
    """A mouse tool.  ``name`` is its button label and key (its place in ``TOOLS``: keys 1..9);
    ``help`` is the one line the Tools panel shows.  Points are world metres.  A tool that also
    drops a default body when its palette button is dragged into the scene sets
    ``droppable = True`` and implements :meth:`drop`; a tool that picks bodies (rather than
    placing points) sets ``snaps = False``."""

    name = ""
    help = ""
    droppable = False
    snaps = True          # its points are snapped to the grid while snapping is on (G)

    def __init__(self, editor):
        self.editor = editor

    def press(self, p, button, mods):
        """Left button pressed at world point ``p``."""

    def drag(self, p):
        """Pointer moved to ``p`` with the left button held."""

    def release(self, p):
        """Left button released at ``p``."""

    def right_click(self, p) -> bool:
        """A right click without a drag at ``p`` (True: the tool used it, no context menu)."""
        return False

    def key(self, symbol) -> bool:
        """A key the tool handles itself (True: consumed, no shortcut fires)."""
        return False

    def cancel(self):
        """Drop whatever is half-done (Esc, another tool, an undo, a new document)."""

    def decorate(self, decor, cursor):
        """Add this frame's previews to ``decor`` (an :class:`app.render.Decor`)."""

    def update(self, cursor):
        """Called every frame before stepping (the mouse joint follows the cursor here)."""

    def drop(self, p):
        """Create this tool's default body at world point ``p`` (palette drag and drop)."""
