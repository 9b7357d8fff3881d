"""Short messages for the user (the strip at the bottom of the scene); errors also go to stderr."""
from __future__ import annotations

import sys
import time


class Notices:
    """``items``: (text, is_error, monotonic time) in the order they were posted."""

    def __init__(self):
        self.items: list[tuple[str, bool, float]] = []

    def notify(self, text: str, error: bool = False) -> None:
        """Post ``text``; an error is also printed to stderr."""
        self.items.append((text, error, time.monotonic()))
        if error:
            print(f"stelkropp: {text}", file=sys.stderr)

    def recent(self, seconds: float = 6.0) -> list[tuple[str, bool, float]]:
        """The messages younger than ``seconds`` (older ones are forgotten)."""
        now = time.monotonic()
        self.items[:] = [m for m in self.items if now - m[2] < seconds]
        return self.items
