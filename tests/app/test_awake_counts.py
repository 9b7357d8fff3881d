"""The stats window's contact figures count a sleeping pile's contacts: a pyramid at rest, every
box asleep, still reads its touching pairs, as it did awake (a 0 there read as "nothing
touches").  The pairs figure is world.info()'s, the contacts plot world.contact_depths()'s."""
from __future__ import annotations

import pytest

from sandbox_pixels import ROOT

pytestmark = pytest.mark.app


def test_a_sleeping_pile_still_shows_its_contacts(launch):
    app = launch(ROOT / "scenes" / "pyramid.json")
    app.wait_ready(20)
    st = app.wait(lambda s: s["ui_values"].get("stats_counts", {}).get("contacts", 0) > 0, 20, "the pairs counted")
    awake_pairs = st["ui_values"]["stats_counts"]["contacts"]
    # the slider's 4x: the pile falls asleep within a few simulated seconds
    app.set_time_scale(4)
    st = app.wait(lambda s: s["ui_values"]["stats_counts"]["awake"] == 0, 120, "every box asleep")
    st = app.settle()
    counts = st["ui_values"]["stats_counts"]
    assert counts["awake"] == 0 and counts["bodies"] == st["n_bodies"]
    # 20 rows of boxes on the ground: 400 touching pairs here, awake and asleep (a box that
    # settles may lose or gain a pair, never the pile)
    assert counts["contacts"] >= 0.9 * awake_pairs > 0, (counts, awake_pairs)
    assert st["ui_values"]["stats_contacts"] == counts["contacts"]
