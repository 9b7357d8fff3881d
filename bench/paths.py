"""Where the benchmark reads and writes: the repository root, the shipped scenes, results, docs."""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCENES = ROOT / "scenes"
RESULTS = Path(__file__).resolve().parent / "results"
DOCS = ROOT / "docs" / "benchmarks.md"
RELIABILITY_DOC = ROOT / "docs" / "reliability.md"
DOCS_NOTES = RESULTS / "notes.md"
