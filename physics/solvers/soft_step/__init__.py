"""``soft_step``: sub-stepped soft contacts (Box2D v3 style), the default mode."""
