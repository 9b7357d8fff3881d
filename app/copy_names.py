"""Names for copies (paste, duplicate): a name must stay unique, so a copy of "crate" is "crate
copy", then "crate copy 2", ... (the first free one); an unnamed original gives an unnamed copy."""
from __future__ import annotations


def copy_name(name, taken: set):
    """A free name for a copy of ``name`` (None stays None); the result is added to ``taken``."""
    if name is None:
        return None
    base = f"{name} copy"
    out, k = base, 1
    while out in taken:
        k += 1
        out = f"{base} {k}"
    taken.add(out)
    return out


def world_names(world) -> set:
    """Every name the world's bodies, springs and joints have now."""
    items = list(world.bodies) + list(world.springs) + list(world.joints)
    return {x.name for x in items if x.name is not None}
