"""Collision detection: the broad phase (pairs of overlapping AABBs) and the narrow phase
(contact manifolds with feature ids for the pairs)."""
