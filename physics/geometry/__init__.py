"""Shapes as value objects (validated in Python) and their world-space geometry (a kernel)."""
