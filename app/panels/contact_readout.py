"""The stats window's contact readout: the selected body's contacts with their normal and
tangent impulses per manifold point (``world.contacts()``, N s over the last step), one of them
picked to show in full, and the body's contact hits per second (the core's hit events:
``app.contact_events``)."""
from __future__ import annotations

import physics
from imgui_bundle import imgui

from .base import record
from .style import DIM

MAX_LISTED = 6
BUDGET_MS = 2.0      # world.contacts() is a Python loop (~23 ms for 1000 contacts): at most this a frame on average


class ContactReadout:
    def __init__(self, app):
        from ..contact_events import HitRate
        self.app = app
        self.rate = HitRate()
        self.picked = None          # the fixture pair shown in full
        self._cache = (None, [])     # ((body id, steps, edit version), its contacts)
        self._skip = 0               # frames to wait before asking the core again (a big scene)

    def body(self):
        sel = [s for s in self.app.editor.selection if s.alive and isinstance(s, physics.Body)]
        return sel[-1] if sel else None

    def contacts_of(self, b):
        """``b``'s contacts from ``world.contacts()``, asked again only after a step or an edit,
        and in a scene with many contacts only every few frames (BUDGET_MS a frame on average;
        the hit rate then sees the begins at that coarser rate)."""
        import time
        w = self.app.world
        key = (b.id, w.steps, self.app.editor.doc.history.version, id(w))
        if key == self._cache[0] or (self._skip > 0 and self._cache[0] is not None and self._cache[0][0] == b.id):
            self._skip -= 1
            return self._cache[1]
        t0 = time.perf_counter()
        contacts = [c for c in w.contacts() if c.body_a.id == b.id or c.body_b.id == b.id]
        self._skip = int((time.perf_counter() - t0) * 1e3 / BUDGET_MS)
        self._cache = (key, contacts)
        return contacts

    def draw(self):
        """One line per contact of the selected body (click one to pick it), the picked one's
        impulses per point, and the hit rate.  Nothing (and no cost) without a selected body."""
        from ..contact_events import pair_key
        app, b = self.app, self.body()
        app.ui_values["contacts"] = None
        if b is None:
            self.rate.body = None   # no body watched: the step loop asks the core nothing
            return
        contacts = self.contacts_of(b)
        self.rate.update(app.world, b.id, contacts)
        keys = [pair_key(c) for c in contacts]
        if self.picked not in keys:
            self.picked = keys[0] if keys else None
        imgui.text(f"{b.name or b.id}: {len(contacts)} contacts   hits {self.rate.per_second():.1f}/s")
        record(app, "stats:contacts")
        rows, picked = [], None
        for c, k in zip(contacts[:MAX_LISTED], keys):
            other = c.body_b if c.body_a.id == b.id else c.body_a
            rows.append({"other": other.id, "pair": list(k), "normal_impulses": list(c.normal_impulses),
                         "tangent_impulses": list(c.tangent_impulses)})
            if k == self.picked:
                picked = c
            imgui.same_line()
            if imgui.selectable(f"{other.name or other.id}##c{k}", k == self.picked,
                                size=imgui.ImVec2(70, 0))[0]:
                self.picked = k
        if picked is not None:
            pts = "   ".join(f"p{i}: normal {jn:.4g}  tangent {jt:.4g}"
                           for i, (jn, jt) in enumerate(zip(picked.normal_impulses, picked.tangent_impulses)))
            imgui.text_colored(DIM, f"impulses (N s, last step)   {pts}")
        app.ui_values["contacts"] = {"body": b.id, "contacts": rows, "picked": self.picked and list(self.picked),
                                     "hits_per_second": self.rate.per_second(), "hit_times": list(self.rate.times)}
        if len(contacts) > MAX_LISTED:
            imgui.text_colored(DIM, f"... and {len(contacts) - MAX_LISTED} more")
