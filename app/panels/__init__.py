"""The sandbox's imgui panels, one module per panel (see ``host.SECTIONS`` for the side panel)."""
from .host import SECTIONS, Panels
from .style import PANEL_W, STATS_H, apply_style

__all__ = ["PANEL_W", "Panels", "SECTIONS", "STATS_H", "apply_style"]
