"""``sequential_impulse``: projected Gauss-Seidel with warm starting (Box2D 2.x / Chipmunk style)."""
