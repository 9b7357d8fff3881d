"""Every joint tool picks the bodies the select tool picks: a capsule, and each arm of a concave L
drawn clockwise with the polygon tool (one body of convex pieces), whatever the point."""
from __future__ import annotations

import pytest

from sandbox_pixels import pink_pixels
from test_joint_tools import new_joint, pick_tool, to_screen
from test_shape_tools import L_OUTLINE, new_bodies, scene

pytestmark = pytest.mark.app

CAPSULE = {"name": "cap", "shape": {"capsule": {"a": [-0.9, 0.0], "b": [0.9, 0.0], "radius": 0.3}},
           "position": [-6.0, 4.0]}
WHEELS = [{"name": "wh_cap", "shape": {"circle": 0.2}, "position": [-5.2, 4.0]},
          {"name": "wh_l", "shape": {"circle": 0.2}, "position": [2.5, 2.7]}]
SHIFT = 4.0          # the L is drawn 4 m right of the shape tools' test's L, clockwise

#: (tool, how it is used at a point of the target: click, or a drag 2 m up, the point)
USES = {"cap": [("hinge", "click", (-6.6, 4.1)), ("motor", "click", (-6.0, 4.0)), ("fixate", "click", (-5.6, 3.9)),
                ("slider", "drag", (-6.75, 4.0)), ("rope", "drag", (-6.3, 4.2)), ("wheel", "click", (-5.2, 4.0))],
        "L": [("hinge", "click", (2.3, 2.0)), ("motor", "click", (2.7, 2.2)), ("fixate", "click", (2.5, 1.8)),
              ("slider", "drag", (2.2, 2.4)), ("rope", "drag", (2.8, 2.4)), ("wheel", "click", (2.5, 2.7))]}


@pytest.mark.slow
def test_joint_tools_pick_capsules_and_every_piece_of_a_concave_body(launch, tmp_path):
    app = launch(scene(tmp_path / "picking.json", [CAPSULE, *WHEELS]), "--paused")
    st0 = app.wait_ready(20)
    pick_tool(app, "polygon")
    for x, y in reversed(L_OUTLINE):                 # clockwise
        app.click(*to_screen(st0, (x + SHIFT, y)))
        app.settle()
    app.key("Return")
    st = app.wait(lambda s: len(s["bodies"]) == len(st0["bodies"]) + 1, 20, "the L")
    (ell,) = new_bodies(st, st0)
    assert ell["fixtures"] == ["polygon", "polygon"], ell
    target = {"cap": next(b["id"] for b in st0["bodies"] if b["name"] == "cap"), "L": ell["id"]}
    n = 0
    for name, uses in USES.items():
        for tool, how, p in uses:
            pick_tool(app, tool)
            if how == "click":
                app.click(*to_screen(st0, p))
            else:
                app.drag(to_screen(st0, p), to_screen(st0, (p[0], p[1] + 2.0)), steps=10)
                app.xdo("mouseup", 1)
            n += 1
            st, j = new_joint(app, n, f"the {tool} tool's joint on {name} (hint: {app.status()['hint']})")
            assert target[name] in (j["a"], j["b"]), (tool, name, j)
    app.key("Escape")
    st = app.frames(4)
    img = app.screenshot("joints_on_capsule_and_L")
    for name, uses in USES.items():
        x, y = to_screen(st, uses[0][2])             # the hinge's pin
        assert pink_pixels(img, x - 8, y - 8, x + 8, y + 8) > 15, f"no hinge drawn on {name}"
    assert not st["gl_errors"] and not st["fault"]
