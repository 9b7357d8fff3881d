"""Griffe extension (mkdocs.yml): Sphinx roles in docstrings become mkdocstrings cross-references.

Docstrings in physics/ may write ``:class:`~physics.World``` or ``:meth:`step``` (reST habit,
and what editors show); mkdocstrings reads Markdown, where those would print literally.
Each becomes an autorefs link, ``[World][physics.World]`` / ``[step][step]``, resolved
relative to the documented object (``scoped_crossrefs``); a target that does not exist fails
the strict build, like a broken link.
"""
from __future__ import annotations

import re

import griffe

ROLE = re.compile(r":(?:py:)?(?:class|meth|func|attr|mod|obj|exc|data|const|prop):`(~?)([\w.]+)(?:\(\))?`")


def markdown_refs(text: str) -> str:
    """``:meth:`~a.b.c``` -> ``[`c`][a.b.c]``; ``:meth:`x``` -> ``[`x`][x]``."""
    def sub(m):
        short, target = m.group(1), m.group(2)
        label = target.rsplit(".", 1)[-1] if short else target
        return f"[`{label}`][{target}]"
    return ROLE.sub(sub, text)


class SphinxRoles(griffe.Extension):
    """Rewrite the roles in every docstring griffe loads."""

    def on_object(self, *, obj, **kwargs) -> None:  # griffe >= 1.x: every module, class, function, attribute
        if obj.docstring is not None:
            obj.docstring.value = markdown_refs(obj.docstring.value)
