"""Letters typed into a number field are refused in words, beside the field.

imgui's number fields drop, as it is typed, every character a number cannot hold: "abc" typed
into the step rate left the field as it was and said nothing, so a refused key looked like a lost
one.  Each number field notes itself here while it has the keyboard (``note``, right after its
widget); the characters then typed (pyglet's ``on_text``, which reaches the scene's handlers after
imgui's) that the field drops are refused through the editor, with the field's label, and the
refusal bubble shows them beside that field."""
from __future__ import annotations

from imgui_bundle import imgui

# what imgui's filters let through: scientific for float fields, decimal for integer ones
NUMBER_CHARS = frozenset("0123456789.+-*/eE")
INTEGER_CHARS = frozenset("0123456789.+-*/")


def _text(field_id):
    """The text in the number field ``field_id`` (None: not a text entry)."""
    state = imgui.internal.get_input_text_state(field_id)
    return None if state is None else state.get_text()


class NumberTyping:
    def __init__(self, app):
        self.app = app
        self.field = None        # (label, rect, allowed chars, imgui id, its text when it took the
        #                          keyboard) of the number field with the keyboard
        self._drawing = None     # the same, noted while this frame's panels are drawn
        self.rejected = ""       # what the field dropped since it took the keyboard

    def begin_frame(self):
        self._drawing = None

    def end_frame(self):
        """The field noted this frame is the one keys typed before the next frame go to."""
        drawing = self._drawing
        if drawing is None or self.field is None or drawing[3] != self.field[3]:
            self.rejected = ""
        self.field = drawing

    def note(self, label, integer=False):
        """Call right after a number widget: ``label`` is how the refusal names it."""
        if imgui.is_item_active():
            a, b = imgui.get_item_rect_min(), imgui.get_item_rect_max()
            chars = INTEGER_CHARS if integer else NUMBER_CHARS
            fid = imgui.internal.get_active_id()
            held = self.field is not None and self.field[3] == fid
            shown = self.field[4] if held else _text(fid)       # its text when it took the keyboard
            self._drawing = (label, (a.x, a.y, b.x, b.y), chars, fid, shown)

    def entered_unedited(self, label) -> bool:
        """Did Enter end ``label``'s entry with its text as it was shown?  imgui then parses the
        shown text back: a value shown rounded (an angle of -30.4220 deg as "-30.42") was set to
        the rounding, and the scene marked edited, by a mere Enter."""
        enter = imgui.is_key_pressed(imgui.Key.enter) or imgui.is_key_pressed(imgui.Key.keypad_enter)
        if not enter or self.field is None or self.field[0] != label or self.field[4] is None:
            return False
        return _text(self.field[3]) == self.field[4]

    def dropped_from(self, label) -> bool:
        """Did the field ``label`` drop characters since it took the keyboard?"""
        return bool(self.rejected) and self.field is not None and self.field[0] == label

    def on_text(self, text):
        if self.field is None or not imgui.get_io().want_text_input:
            return
        label, rect, allowed = self.field[:3]
        dropped = "".join(c for c in text if c.isprintable() and c not in allowed)
        if not dropped:
            return
        first = not self.rejected
        self.rejected += dropped
        example = "60 or -2" if allowed is INTEGER_CHARS else "60, 0.5 or 1e3"
        ed = self.app.editor
        ed.refuse(f'{label}: "{self.rejected}" is not a number; type digits, e.g. {example}', at=rect)
        if first:             # the log says it once an entry; the bubble follows every key
            ed.notify(f"refused: {ed.edit_error}", error=True)


def typed(app, label, changed, integer=False) -> bool:
    """Right after a number widget that returned ``changed``: note it as ``label`` while it has the
    keyboard.  True when its value is to be taken: not when letters were dropped from the entry
    (Enter then applied what was left of it, the old value or the digits around the letters), nor
    when Enter came without a key typed (the shown text, maybe rounded, parsed back)."""
    numbers = app.panels.numbers
    numbers.note(label, integer)
    return changed and not numbers.dropped_from(label) and not numbers.entered_unedited(label)
