"""What every panel shares: the Section interface of the side panel, and rectangle recording
(tests click widgets by the rectangles the status file reports; the scene is framed beside the
panels' windows)."""
from __future__ import annotations

from imgui_bundle import imgui


def record(app, key):
    """Remember the last item's screen rectangle (x0, y0, x1, y1; y down) for tests and scripts."""
    a, b = imgui.get_item_rect_min(), imgui.get_item_rect_max()
    app.ui_rects[key] = (a.x, a.y, b.x, b.y)


def record_window(app, key):
    """Remember the current window's rectangle."""
    a, b = imgui.get_window_pos(), imgui.get_window_size()
    app.ui_rects[key] = (a.x, a.y, a.x + b.x, a.y + b.y)


def wrapped(color, text):
    """Coloured text wrapped at the window's edge."""
    imgui.push_text_wrap_pos(0)
    imgui.text_colored(color, text)
    imgui.pop_text_wrap_pos()


class Section:
    """One collapsing section of the side panel.  ``title`` is its header, ``default_open``
    whether it starts expanded; :meth:`draw` fills it (``self.app`` is the Sandbox).  To add a
    section: subclass this in its own module and list it in ``panels.host.SECTIONS``."""

    title = ""
    default_open = True

    def __init__(self, app):
        self.app = app

    def force_open(self) -> bool:
        """True to expand the section this frame (e.g. to show an error)."""
        return False

    def header(self) -> bool:
        if self.force_open():
            imgui.set_next_item_open(True)
        flags = imgui.TreeNodeFlags_.default_open.value if self.default_open else 0
        opened = imgui.collapsing_header(self.title, flags)
        record(self.app, f"section:{self.title}")
        return opened

    def draw(self):
        raise NotImplementedError
