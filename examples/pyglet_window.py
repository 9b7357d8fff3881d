"""Drive the core from a plain pyglet window of your own (no sandbox, no imgui).

Loads a scene, steps it 60 times a second and draws every body with pyglet's shapes at its
origin and angle, springs as lines. Escape closes it; `--frames N` stops after N frames and
`--screenshot FILE` saves the last one.

Run: `python examples/pyglet_window.py [SCENE] [--frames N] [--screenshot FILE]` (needs `.[app]`)
"""
import argparse
import math

import pyglet
from pyglet import shapes

import physics

ap = argparse.ArgumentParser(description="Stelkropp in a plain pyglet window")
ap.add_argument("scene", nargs="?", default="scenes/default.json")
ap.add_argument("--frames", type=int, help="close after this many frames")
ap.add_argument("--screenshot", help="save the last frame as a PNG")
args = ap.parse_args()

world = physics.load_scene(args.scene)
window = pyglet.window.Window(960, 600, caption=f"Stelkropp: {args.scene}")
batch = pyglet.graphics.Batch()
cam = world.metadata.get("camera", {"center": (0, 8), "zoom": 20})  # as the scene file says
(cx, cy), zoom = cam["center"], cam["zoom"]  # zoom: pixels per metre


def to_screen(x, y):
    return (x - cx) * zoom + window.width / 2, (y - cy) * zoom + window.height / 2


COLOURS = {"dynamic": (230, 160, 60), "static": (110, 120, 140), "kinematic": (90, 170, 220)}
sprites = []  # (body, pyglet shape): built once, moved every frame
for body in world.bodies:
    colour = tuple(min(255, c + 25 * (body.id % 3)) for c in COLOURS[body.kind])  # neighbours differ
    if isinstance(body.shape, physics.Circle):
        sprites.append((body, shapes.Circle(0, 0, body.shape.radius * zoom, color=colour, batch=batch)))
    else:
        pts = [(x * zoom, y * zoom) for x, y in body.shape.vertices]
        poly = shapes.Polygon(*pts, color=colour, batch=batch)
        poly.anchor_position = (-pts[0][0], -pts[0][1])  # rotate and place about the body origin
        sprites.append((body, poly))
springs = [(sp, shapes.Line(0, 0, 0, 0, thickness=2, batch=batch)) for sp in world.springs]
state = {"frames": 0}


def update(dt):
    world.step()
    for body, sprite in sprites:
        if isinstance(sprite, shapes.Circle):
            sprite.position = to_screen(*body.local_to_world(body.shape.offset))
        else:
            sprite.position = to_screen(*body.position)
            sprite.rotation = -math.degrees(body.angle)  # pyglet turns clockwise
    for sp, line in springs:
        (ax, ay), (bx, by) = sp.endpoints()
        (line.x, line.y), (line.x2, line.y2) = to_screen(ax, ay), to_screen(bx, by)


@window.event
def on_draw():
    window.clear()
    batch.draw()
    state["frames"] += 1
    if args.frames and state["frames"] >= args.frames:
        if args.screenshot:  # the frame just drawn, before the buffers swap
            pyglet.image.get_buffer_manager().get_color_buffer().save(args.screenshot)
        print(f"drew {state['frames']} frames of {len(sprites)} bodies; t = {world.time:.2f} s")
        pyglet.app.exit()


update(0)  # place everything before the first frame
pyglet.clock.schedule_interval(update, 1 / 60)
pyglet.app.run()
