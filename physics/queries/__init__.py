"""Spatial queries over a world's fixtures: ray casts, box, point and shape overlap, shape casts.

Each query runs in compiled code over a bounding-volume tree of the fixtures' exact world
boxes (tree.py), built lazily from the current body state and kept until the next step or
edit (cache.py); the per-shape tests are exact for every fixture shape (ray.py, distance.py).
"""
