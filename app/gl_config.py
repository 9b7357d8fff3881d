"""The window's OpenGL config: 4x multisampling (smooth edges) when the driver offers it, else
the plain config. ``STELKROPP_MSAA_SAMPLES`` sets the samples asked for (0: no multisampling;
an impossible number, such as 1024, forces the fallback, which the tests use).

Unless that variable asks for it, a software rasterizer (Mesa's llvmpipe, softpipe, SwiftShader)
gets the plain config: it shades every sample on the CPU, and 4x cost the sandbox ~3x its draw time
under Xvfb here (2 bodies: 83 ms a frame under load), which starved everything else the two cores
ran (a Find settings search timed out).  A hidden 1x1 window with the plain config tells which
renderer the driver gives (``renderer``)."""
from __future__ import annotations

import os

import pyglet
from pyglet.window import NoSuchConfigException

DEFAULT_SAMPLES = 4
BASE = dict(major_version=3, minor_version=3, forward_compatible=True, double_buffer=True,
            red_size=8, green_size=8, blue_size=8, alpha_size=8, depth_size=0)


SOFTWARE = ("llvmpipe", "softpipe", "swrast", "swiftshader", "software")


def samples_wanted():
    """The samples to ask for: STELKROPP_MSAA_SAMPLES if set (not a number: the default), else None
    (the default, 4, unless the renderer is software)."""
    raw = os.environ.get("STELKROPP_MSAA_SAMPLES")
    if raw is None:
        return None
    try:
        return max(0, int(raw))
    except ValueError:
        return DEFAULT_SAMPLES


def renderer() -> str:
    """The GL renderer string the driver gives a plain-config window ('' if none opens)."""
    try:
        probe = pyglet.window.Window(1, 1, visible=False, config=plain())
    except Exception:  # noqa: BLE001  (no probe: the real window's creation reports the problem)
        return ""
    try:
        return pyglet.gl.gl_info.get_renderer() or ""
    finally:
        probe.close()


def is_software(name: str) -> bool:
    """Is ``name`` (a GL renderer string) a CPU rasterizer?"""
    return any(s in name.lower() for s in SOFTWARE)


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
    software = ""
    if want is None:
        name = renderer()
        software = name if is_software(name) else ""
        want = 0 if software else DEFAULT_SAMPLES
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
    elif software:
        used["fallback"] = f"software renderer ({software}): multisampling off (STELKROPP_MSAA_SAMPLES=4 turns it on)"
        log(f"stelkropp: GL config: plain ({used['fallback']})")
    else:
        used["fallback"] = "multisampling off (STELKROPP_MSAA_SAMPLES=0)"
        log("stelkropp: GL config: plain (multisampling off)")
    create(plain())
    return used
