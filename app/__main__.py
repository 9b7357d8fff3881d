"""``python -m app [SCENE]`` / ``stelkropp [SCENE]``: the Stelkropp sandbox."""
from __future__ import annotations

import argparse
import sys


def parse_args(argv=None):
    ap = argparse.ArgumentParser(prog="stelkropp", description="Stelkropp 2D physics sandbox")
    ap.add_argument("scene", nargs="?", help="scene file (default: scenes/default.json)")
    ap.add_argument("--size", default="1280x800", help="window size WxH")
    ap.add_argument("--position", default=None, help="window position X,Y")
    ap.add_argument("--paused", action="store_true", help="start paused")
    ap.add_argument("--frames", type=int, default=None, help="stop after N frames once the scene is ready")
    ap.add_argument("--screenshot", default=None, help="save a PNG of the last frame (with --frames)")
    ap.add_argument("--exit", action="store_true", help="exit after --frames (status 3 on any OpenGL error)")
    ap.add_argument("--tour", nargs="+", metavar="SCENE", default=None,
                    help="then open each SCENE in turn, --frames frames each; --screenshot is then a folder "
                         "that receives <scene>.png and <scene>.json per scene (app/tour.py); exits after the last")
    ap.add_argument("--tour-seconds", type=float, default=0.0,
                    help="with --tour: also run each scene this many simulated seconds before its screenshot")
    ap.add_argument("--benchmark-frames", type=int, default=None,
                    help="run N frames unthrottled, one physics step each, and print the frame-time split")
    ap.add_argument("--plot", action="store_true",
                    help="open the Plot tab with four quantities of the first dynamic body (a benchmark's load)")
    ap.add_argument("--hide-ui", action="store_true", help="start with the panels hidden (H toggles)")
    ap.add_argument("--no-stats", action="store_true", help="start with the stats window closed")
    ap.add_argument("--bodies", type=int, default=None, help="instead of a scene: N dynamic bodies in a box")
    ap.add_argument("--status", default=None, help="write a JSON status file every few frames (tests)")
    ap.add_argument("--control", default=None,
                    help="a file of JSON event lines to dispatch into the window (test driver)")
    ap.add_argument("--autosave-interval", type=float, default=60.0, help="seconds between autosaves")
    ap.add_argument("--no-autosave-offer", action="store_true", help="do not offer a crashed session's autosave")
    return ap.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(argv)
    import pyglet
    pyglet.options["debug_gl"] = False
    from physics.step.one_call import compile_on_demand

    from .loop import MainLoop
    from .window import Sandbox
    # a world whose one-call step is not compiled yet plays through the pipeline's stages while
    # the compile helper makes it (app/warmup.py); no step stops the window to compile it
    compile_on_demand(False)
    size = tuple(int(v) for v in args.size.lower().split("x"))
    pos = tuple(int(v) for v in args.position.split(",")) if args.position else None
    world = None
    if args.bodies:
        from .scenes import bench_world
        world = bench_world(args.bodies)
    win = Sandbox(scene=args.scene, world=world, size=size, position=pos, paused=args.paused,
                  autosave_interval=args.autosave_interval, offer_autosave=not args.no_autosave_offer)
    win.show_ui = not args.hide_ui
    win.panels.show_stats = not args.no_stats
    if args.plot:
        plot_first_body(win)
    loop = MainLoop(win)
    frames = args.frames
    if frames is None and args.benchmark_frames:
        frames = args.benchmark_frames + 10
    if args.tour:
        from .tour import Tour
        Tour(args.tour, frames or 120, args.screenshot or ".", args.tour_seconds).attach(loop)
    elif args.status or args.control or args.screenshot or args.exit:
        from .automation import Automation
        Automation(args.status, args.control, frames, args.screenshot, args.exit).attach(loop)
    if args.benchmark_frames:
        from .benchmark import FrameBenchmark
        FrameBenchmark(args.benchmark_frames).attach(loop)
    return loop.run()


PLOTTED = ("x", "y", "speed", "kinetic energy")


def plot_first_body(win) -> None:
    """Record PLOTTED of the first dynamic body and show the Plot tab (what a user who plots one
    body sees; ``--benchmark-frames`` then times frames with those plots drawn)."""
    ed = win.editor
    body = next((b for b in ed.world.bodies if b.kind == "dynamic"), None)
    if body is None:
        return
    for q in PLOTTED:
        win.recorder.toggle(body, q, ed.refs, ed.world)
    win.panels.plot.show()


if __name__ == "__main__":
    sys.exit(main())
