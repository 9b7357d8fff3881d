"""Shared test setup: the repository root is importable without an install, and the tests' own
helper modules (builders, end_states, extreme_pins, seed_scenes) from every test directory."""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
for path in (ROOT, ROOT / "tests"):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))
