"""The one line a scene shows at the top of the free area: what to try in it.

It is the sentence of the scene's description that starts with "Try" (the shipped scenes whose
point is not obvious at a glance end their description with one).  Scenes without one show no
caption, so old and user files load and look as before."""
from __future__ import annotations

import re

_SENTENCE = re.compile(r"(?<=[.!?])\s+")


def caption_of(metadata: dict) -> str | None:
    """The description's first sentence that starts with "Try", or None."""
    text = metadata.get("description")
    if not isinstance(text, str):
        return None
    for sentence in _SENTENCE.split(text.strip()):
        if sentence.startswith("Try"):
            return sentence
    return None
