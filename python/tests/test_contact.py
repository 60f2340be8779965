"""Collision from Python: load(collision=True, contact="smc") makes the seed's collision shapes
collide through SMC penalty contact (docs/contact.md), as `sinew simulate --collision` does."""
import math

import sinew
from conftest import DATA

BALL = DATA / "sinew" / "ball_on_floor.osim"


def test_ball_rests_at_hertz_static_depth_with_smc():
    # A 1 kg ball of radius 0.1 m (ContactSphere) dropped 0.2 m on the ContactHalfSpace floor,
    # default material (E = 1e7 Pa, nu = 0.3 for both: E* = E / (2 (1 - nu^2))). At rest
    # the Hertz force 4/3 E* sqrt(R) d^(3/2) carries the weight m g, so the centre rests at
    # R - d with d = (3 m g / (4 E* sqrt(R)))^(2/3) = 0.26 mm. The bounces (restitution 0.4)
    # die out by 0.5 s and the damping's decay time is a few ms; rk45 at 1e-8 resolves d to
    # far better than the 1 um asserted.
    model = sinew.load(BALL, collision=True, contact="smc")
    result = model.simulate(1.5, accuracy=1e-8, report_interval=0.05)
    ty = result.q[:, result.coordinates.index("ty")]
    radius, mass, g = 0.1, 1.0, 9.80665
    e_star = 1e7 / (2.0 * (1.0 - 0.3 ** 2))
    depth = (3.0 * mass * g / (4.0 * e_star * math.sqrt(radius))) ** (2.0 / 3.0)
    assert abs(ty[0] - 0.3) < 1e-12
    assert abs(ty[-1] - (radius - depth)) < 1e-6, (ty[-1], radius - depth)
    assert abs(result.u[-1, result.coordinates.index("ty")]) < 1e-4
