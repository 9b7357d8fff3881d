"""The window's OpenGL config: 4x multisampling (smooth edges) when the driver offers it, else
the plain config. ``STELKROPP_MSAA_SAMPLES`` sets the samples asked for (0: no multisampling;
an impossible number, such as 1024, forces the fallback, which the tests use)."""
from __future__ import annotations

import os

import pyglet
from pyglet.window import NoSuchConfigException

DEFAULT_SAMPLES = 4
BASE = dict(major_version=3, minor_version=3, forward_compatible=True, double_buffer=True,
            red_size=8, green_size=8, blue_size=8, alpha_size=8, depth_size=0)


def samples_wanted() -> int:
    """The samples to ask for (STELKROPP_MSAA_SAMPLES, default 4; not a number: the default)."""
    raw = os.environ.get("STELKROPP_MSAA_SAMPLES", str(DEFAULT_SAMPLES))
    try:
        return max(0, int(raw))
    except ValueError:
        return DEFAULT_SAMPLES


def plain() -> pyglet.gl.Config:
    """The config every GL 3.3 driver the sandbox runs on offers (the fallback)."""
    return pyglet.gl.Config(**BASE)


def multisampled(samples: int) -> pyglet.gl.Config:
    """The plain config with a multisampled framebuffer (smooth edges)."""
    return pyglet.gl.Config(**BASE, sample_buffers=1, samples=samples)


def log_line(text: str) -> None:
    print(text, flush=True)     # the log is a file in tests: flushed, so it is there at once


def create_window(create, log=log_line) -> dict:
    """Call ``create(config)`` (which builds the window) with the multisampled config, and with the
    plain one if the driver refuses it (no such config, or the context cannot be made). Returns
    what was used: {"msaa", "samples_requested", "fallback"} (the reason, or None)."""
    want = samples_wanted()
    used = {"msaa": False, "samples_requested": want, "fallback": None}
    if want > 0:
        try:
            create(multisampled(want))
            used["msaa"] = True
            log(f"stelkropp: GL config: {want}x multisampling")
            return used
        except (NoSuchConfigException, pyglet.gl.ContextException) as exc:
            used["fallback"] = f"{type(exc).__name__}: {exc}".rstrip(": ")
            log(f"stelkropp: GL config: {want}x multisampling refused ({used['fallback']}); plain config")
    else:
        used["fallback"] = "multisampling off (STELKROPP_MSAA_SAMPLES=0)"
        log("stelkropp: GL config: plain (multisampling off)")
    create(plain())
    return used
