"""Box2D v3's Cart sample (``sample_robustness.cpp``), issue 18: a 1000 kg/m^2 chassis on two
0.1 m wheels (about 640 times lighter) on revolute joints, gravity -22, at issue 18's 4 sub-steps.

Bounds: Box2D v3's figures measured on the same description (bench/results/box2d_v3_figures.json,
``bench/box2d/figures_samples.py fig_cart``, 4 sub-steps: chassis sink 0.2501 m (its wheels pushed
into the ground, the chassis resting on it), rms vertical speed over 5..10 s 4.3e-7 m/s, axle
separation 0.0295 m), each max(|b| * 1.05, 1e-3) as docs/reliability.md judges.  Before the
deep-overlap softening (constraints/contact_soft.py DEEP) ours kept bouncing (1.29 m/s rms): the
wheels' contacts, soft for a wheel's mass but carrying the chassis, sank past DEEP and pushed out
at push_out_speed with a warm-started impulse several times the weight.
"""
from bench.box2d.figures_samples import fig_cart

from accuracy_common import box2d, ours


def test_cart_on_light_wheels_comes_to_rest_at_four_substeps():
    figs = ours(fig_cart)
    for name in ("chassis_sink_10s", "chassis_vy_rms_5_10s", "max_joint_separation_5_10s"):
        key = f"cart.{name}.substeps4"
        print(f"{key}: ours {figs[key]:.4g}, Box2D v3 {box2d(key):.4g}")
        assert abs(figs[key]) <= max(1.05 * abs(box2d(key)), 1e-3), key
