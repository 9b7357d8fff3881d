"""The panels' look: colours, the default panel widths, and the imgui style."""
from __future__ import annotations

from imgui_bundle import imgui

RED = imgui.ImVec4(1.0, 0.45, 0.42, 1.0)
AMBER = imgui.ImVec4(1.0, 0.8, 0.35, 1.0)
DIM = imgui.ImVec4(0.62, 0.66, 0.72, 1.0)
GREEN = imgui.ImVec4(0.5, 0.9, 0.6, 1.0)
PANEL_W = 340          # the side panel's default width (px)
STATS_H = 290          # the stats window's default height (px): a strip along the bottom
ENTER = imgui.InputTextFlags_.enter_returns_true.value
#: the side panel's longest fixed labels: widgets leave room for these, so no label is clipped
#: (the solver settings' names are measured as well, see ``label_room``)
LABELS = ("step rate (Hz)", "time scale", "new body kind", "click size (m)", "mouse joint Hz",
          "restitution", "spring k", "n-gon sides", "angle (deg)", "angular vel.", "static friction",
          "dynamic friction", "anchor a (local)", "anchor b (world)", "rest length", "narrow phase",
          "broad phase", "integrator", "bound min (m)", "bound max (m)", "trail seconds")


def label_room(extra=()) -> float:
    """Pixels to keep right of a widget for the longest label of ``LABELS`` and ``extra``."""
    widest = max(imgui.calc_text_size(s).x for s in (*LABELS, *extra))
    return widest + 2 * imgui.get_style().item_inner_spacing.x + 4


def apply_style():
    """Dark theme, rounded corners, and no anti-aliasing (llvmpipe pays per triangle)."""
    imgui.style_colors_dark()
    st = imgui.get_style()
    st.window_rounding = 6.0
    st.frame_rounding = 4.0
    st.grab_rounding = 4.0
    st.popup_rounding = 4.0
    st.window_border_size = 0.0
    # fewer, simpler triangles: llvmpipe pays per triangle far more than per pixel
    st.anti_aliased_lines = False
    st.anti_aliased_fill = False
    st.frame_padding = imgui.ImVec2(6, 3)
    st.item_spacing = imgui.ImVec2(6, 4)
    colors = {
        imgui.Col_.window_bg: (0.075, 0.085, 0.11, 0.94),
        imgui.Col_.header: (0.20, 0.33, 0.52, 0.55),
        imgui.Col_.header_hovered: (0.26, 0.42, 0.66, 0.8),
        imgui.Col_.header_active: (0.30, 0.48, 0.75, 1.0),
        imgui.Col_.button: (0.20, 0.33, 0.52, 0.65),
        imgui.Col_.button_hovered: (0.28, 0.45, 0.70, 0.9),
        imgui.Col_.frame_bg: (0.13, 0.15, 0.20, 1.0),
        imgui.Col_.title_bg_active: (0.12, 0.18, 0.28, 1.0),
        imgui.Col_.slider_grab: (0.40, 0.62, 0.95, 1.0),
        imgui.Col_.check_mark: (0.55, 0.78, 1.0, 1.0),
    }
    for k, v in colors.items():
        st.set_color_(k, imgui.ImVec4(*v))
