"""The public API contract of physics.World and its handles (issue: Physics core I)."""
import math

import numpy as np
import pytest

import physics
from builders import ground as add_ground


def make_world(**kw):
    kw.setdefault("gravity", (0.0, -9.81))
    w = physics.World(**kw)
    return w, add_ground(w)


def test_contract_names_and_defaults():
    w, ground = make_world(dt=1 / 60, solver="soft_step")
    box = w.add_body(physics.Polygon.box(1, 1), position=(0, 2), angle=0.0, velocity=(0, 0),
                     angular_velocity=0.0, density=1.0, restitution=0.0, friction=0.6, name="box")
    assert w.body("box") is box and w.body("ground") is ground
    assert w.bodies == [ground, box]
    assert box.kind == "dynamic" and ground.kind == "static"
    assert box.mass == pytest.approx(1.0) and box.inertia == pytest.approx(1 / 6)
    assert box.friction == (0.6, 0.6) and box.restitution == 0.0
    w.step()
    assert w.time == pytest.approx(1 / 60)
    w.step(0.01)
    assert w.time == pytest.approx(1 / 60 + 0.01)
    assert box.position[1] < 2.0 and box.velocity[1] < 0.0


def test_state_is_assignable_and_read_back():
    w, _ = make_world()
    b = w.add_body(physics.Polygon.box(2, 1), position=(1, 2))
    b.position = (3.0, 4.0)
    b.angle = 0.5
    b.velocity = (1.0, -2.0)
    b.angular_velocity = 3.0
    assert b.position == pytest.approx((3.0, 4.0))
    assert b.angle == 0.5 and b.velocity == (1.0, -2.0) and b.angular_velocity == 3.0


def test_position_is_body_origin_for_offset_polygons():
    """Vertices are body coordinates; the centre of mass need not be the origin."""
    w = physics.World(gravity=(0, 0))
    tri = physics.Polygon([(0, 0), (3, 0), (0, 3)])
    b = w.add_body(tri, position=(10, 0), angle=0.0)
    assert b.position == pytest.approx((10, 0))
    assert b.center_of_mass == pytest.approx((11, 1))
    b.angle = math.pi / 2  # rotates about the origin, which stays put
    assert b.position == pytest.approx((10, 0))
    assert b.center_of_mass == pytest.approx((9, 1))
    assert b.local_to_world((3, 0)) == pytest.approx((10, 3))
    assert b.world_to_local((10, 3)) == pytest.approx((3, 0))


def test_friction_pair_and_combination_rules():
    w, ground = make_world()
    ground.friction = (0.9, 0.4)
    ground.restitution = 0.2
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.49), friction=(0.4, 0.1), restitution=0.7)
    assert b.friction == (0.4, 0.1)
    w.step()
    # the combined friction and restitution of a contact row are not public (world.contacts() gives
    # geometry only): read the contact table
    c = w._contacts.cur
    assert w._contacts.n == 1
    assert c.mu_s[0] == pytest.approx(math.sqrt(0.9 * 0.4))
    assert c.mu_d[0] == pytest.approx(math.sqrt(0.4 * 0.1))
    assert c.e[0] == pytest.approx(0.7)


def test_contacts_report_normal_from_a_to_b_and_depth():
    w, ground = make_world(sleeping=False)
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.45))  # 5 cm into the ground
    w.step()
    cs = w.contacts()
    assert len(cs) == 1
    c = cs[0]
    assert {c.body_a, c.body_b} == {ground, b}
    sign = 1 if c.body_a is ground else -1
    assert sign * c.normal[1] == pytest.approx(1.0, abs=1e-9)
    assert 0.0 < c.depth <= 0.05 + 1e-9
    assert len(c.points) == 2


def test_handles_survive_removal_of_others():
    w, ground = make_world()
    boxes = [w.add_body(physics.Polygon.box(1, 1), position=(i * 2, 1), name=f"b{i}") for i in range(5)]
    w.remove(boxes[1])
    assert not boxes[1].alive
    with pytest.raises(ValueError):
        boxes[1].position
    for i in (0, 2, 3, 4):
        assert boxes[i].position == pytest.approx((i * 2, 1))
        assert w.body(f"b{i}") is boxes[i]
    with pytest.raises(KeyError):
        w.body("b1")
    assert len(w.bodies) == 5
    w.step()
    assert all(np.isfinite(b.position).all() for b in w.bodies)


def test_removing_a_body_removes_its_springs():
    w, ground = make_world()
    a = w.add_body(physics.Polygon.box(1, 1), position=(0, 3))
    b = w.add_body(physics.Polygon.box(1, 1), position=(2, 3))
    s = w.add_spring(a, b, stiffness=10, name="s")
    w.add_spring(b, None, anchor_b=(2, 5), stiffness=10)
    assert s.rest_length == pytest.approx(2.0)
    w.remove(a)
    assert not s.alive and len(w.springs) == 1
    w.step()
    assert np.isfinite(b.position).all()


def test_kinematic_moves_with_its_velocity_and_ignores_gravity_and_contacts():
    w, ground = make_world(sleeping=False)
    k = w.add_body(physics.Polygon.box(4, 0.5), kind="kinematic", position=(0, 0.25), velocity=(1, 0),
                   angular_velocity=0.0)
    box = w.add_body(physics.Polygon.box(1, 1), position=(0, 1.0))
    for _ in range(60):
        w.step()
    assert k.position == pytest.approx((1.0, 0.25), abs=1e-9)
    assert k.velocity == (1.0, 0.0)
    assert k.mass > 0 and box.position[1] > 0.9  # the box rides on it


def test_bad_input_names_the_field():
    w, _ = make_world()
    with pytest.raises(ValueError, match="density"):
        w.add_body(physics.Polygon.box(1, 1), density=-1)
    with pytest.raises(ValueError, match="position"):
        w.add_body(physics.Polygon.box(1, 1), position=(math.nan, 0))
    with pytest.raises(ValueError, match="restitution"):
        w.add_body(physics.Polygon.box(1, 1), restitution=1.5)
    with pytest.raises(ValueError, match="friction"):
        w.add_body(physics.Polygon.box(1, 1), friction=-0.1)
    with pytest.raises(ValueError, match="kind"):
        w.add_body(physics.Polygon.box(1, 1), kind="floating")
    with pytest.raises(ValueError, match="solver"):
        w.solver = "magic"
    b = w.add_body(physics.Polygon.box(1, 1), name="x")
    with pytest.raises(ValueError, match="already exists"):
        w.add_body(physics.Polygon.box(1, 1), name="x")
    with pytest.raises(ValueError, match="velocity"):
        b.velocity = (math.inf, 0)
    with pytest.raises(KeyError, match="no setting"):
        w.settings["nonsense"] = 1
    with pytest.raises(ValueError, match="substeps"):
        w.settings["substeps"] = 0
    assert b.velocity == (0.0, 0.0)  # the refused edit changed nothing


def test_query_point_picks_the_body_under_the_cursor():
    w, ground = make_world()
    b = w.add_body(physics.Polygon.regular(6, 1.0), position=(5, 3))
    c = w.add_body(physics.Circle(0.5), position=(-5, 3))
    assert w.query_point((5, 3)) is b
    assert w.query_point((5.9, 3)) is b
    assert w.query_point((-5.4, 3)) is c
    assert w.query_point((0, -0.5)) is ground
    assert w.query_point((0, 10)) is None


def test_render_data_is_consistent_with_handles():
    w, ground = make_world()
    b = w.add_body(physics.Polygon.box(1, 2), position=(1, 2), angle=0.3)
    rd = w.render_data()
    # render_data() is indexed by storage slot, which has no public accessor
    s = w._bodies.slot_of[b.id]
    verts = rd.vertices[rd.vstart[s]: rd.vstart[s] + rd.vcount[s]]
    assert np.allclose(np.sort(verts, axis=0), np.sort(b.world_vertices(), axis=0))


def test_solver_switch_keeps_per_mode_settings():
    w, _ = make_world()
    w.settings["substeps"] = 8
    assert w.settings["substeps"] == 8
    other = [m for m in w.solvers if m != "soft_step"]
    if other:
        w.solver = other[0]
        w.solver = "soft_step"
        assert w.settings["substeps"] == 8


def test_quadtree_cells_cover_every_body():
    w, ground = make_world()
    for i in range(60):
        w.add_body(physics.Polygon.box(0.5, 0.5), position=((i % 10) - 5, 1 + i // 10))
    cells = w.quadtree_cells()
    assert cells.ndim == 2 and cells.shape[1] == 4 and len(cells) >= 1
    lo = cells[:, :2].min(axis=0)
    hi = cells[:, 2:].max(axis=0)
    for b in w.bodies:
        v = b.world_vertices()
        assert np.all(v >= lo - 0.05) and np.all(v <= hi + 0.05)
