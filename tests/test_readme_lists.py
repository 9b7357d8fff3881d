"""The README names every shipped scene, every tool and the quit key (it named 15 of 28 scenes and
6 of 17 tools, and had a "convex hull" polygon line from before concave outlines)."""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_readme_names_every_scene_and_tool():
    text = (ROOT / "README.md").read_text()
    scenes = sorted(p.stem for p in (ROOT / "scenes").glob("*.json") if p.stem != "stelkropp.schema")
    assert [s for s in scenes if s not in text] == []
    assert f"The {len(scenes)}\nshipped scenes" in text or f"The {len(scenes)} shipped scenes" in text
    from app.tools import TOOLS
    assert [t.name for t in TOOLS if f"| {t.name}" not in text] == []
    assert "Ctrl+Q" in text and "convex hull)" not in text
