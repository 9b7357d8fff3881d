"""What to draw besides the bodies: the overlay switches and this frame's decorations."""
from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class Overlays:
    contacts: bool = False
    aabbs: bool = False
    quadtree: bool = False
    velocities: bool = False
    com: bool = False
    springs: bool = True
    joints: bool = True


@dataclass
class Decor:
    """Extra things to draw this frame (tool previews, mouse joint, selection)."""
    selected_bodies: set = field(default_factory=set)   # body ids
    hovered_body: int | None = None
    selected_springs: set = field(default_factory=set)  # spring ids
    hidden_springs: set = field(default_factory=set)    # spring ids drawn as plain lines (mouse joint)
    selected_joints: set = field(default_factory=set)   # joint ids
    hidden_joints: set = field(default_factory=set)     # joint ids the tools draw themselves (the mouse drag)
    motor_pins: dict = field(default_factory=dict)      # joint id -> angle of the body its motor turns
    segments: list = field(default_factory=list)        # (p0, p1, width_px, rgba)
    points: list = field(default_factory=list)          # (p, radius_px, rgba)
    colors: dict = field(default_factory=dict)          # body id -> (r, g, b) chosen in the inspector
    sensors: dict = field(default_factory=dict)         # sensor fixture id -> lit (app.sensors)
    trails: tuple | None = None                         # (p0 (K, 2), p1 (K, 2), rgba (K, 4)) tracer trails
