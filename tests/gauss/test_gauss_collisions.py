"""Collisions (E1, E4, E6, E24) and impacts on constructions (R10): momentum conserved, energy not increased."""

import numpy as np
import pytest

from lagrange.errors import CollisionError
from lagrange.gauss.balance import kinetic_energy
from lagrange.gauss.collisions import ball_collision, contact_row, impact


def test_e1_identical_balls_exchange_velocities():
    out = ball_collision(1.0, 1.0, (3, 0, 0), (-1, 0, 0), (1, 0, 0))
    assert np.allclose(out.velocities, [[-1, 0, 0], [3, 0, 0]])
    assert np.allclose(out.momentum_change, 0) and out.energy_change == pytest.approx(0, abs=1e-12)


def test_e24_central_and_oblique():
    a = ball_collision(1.0, 3.0, (2, 0, 0), (0, 0, 0), (1, 0, 0))
    assert np.allclose(a.velocities, [[-1, 0, 0], [1, 0, 0]])
    b = ball_collision(1.0, 1.0, (1, 1, 0), (0, 0, 0), (1, 0, 0))
    assert np.allclose(b.velocities, [[0, 1, 0], [1, 0, 0]])


@pytest.mark.parametrize("seed", range(5))
def test_e4_random_collisions_balance_and_frame_independent_defect(seed):
    rng = np.random.default_rng(seed)
    m1, m2, e = rng.uniform(0.3, 3.0), rng.uniform(0.3, 3.0), rng.uniform(0, 1)
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    v1, v2 = rng.normal(size=3), rng.normal(size=3)
    if (v1 - v2) @ n <= 0:
        n = -n
    out = ball_collision(m1, m2, v1, v2, n, e)
    assert np.allclose(out.momentum_change, 0, atol=1e-13)
    vn = (v1 - v2) @ n
    assert out.energy_change == pytest.approx(-0.5 * m1 * m2 / (m1 + m2) * (1 - e**2) * vn**2, rel=1e-10, abs=1e-14)
    assert out.energy_change <= 1e-14
    u = rng.normal(size=3)  # the same collision seen from G(u): same defect, same velocity jumps
    boosted = ball_collision(m1, m2, v1 - u, v2 - u, n, e)
    assert boosted.energy_change == pytest.approx(out.energy_change, rel=1e-9, abs=1e-14)
    assert np.allclose(boosted.velocities + u, out.velocities)
    # the construction route (R10 with one contact row) gives the same outcome
    via_impact = impact([m1, m2], [v1, v2], contact_row(2, 0, 1, n), e=e)
    assert np.allclose(via_impact.velocities, out.velocities, atol=1e-12)


def test_e6_ball_hits_a_barbell_perpendicular_to_the_bar():
    # points: 0, 1 the barbell (m1 = 1, m2 = 2, bar along x), 2 the free ball m_e = 1 moving along y onto point 0
    masses = [1.0, 1.0 * 2, 1.0]
    v = np.array([[0, 0, 0], [0, 0, 0], [0, -2.0, 0]])
    bar = np.zeros(9)
    bar[0:3], bar[3:6] = -np.array([1.0, 0, 0]), [1.0, 0, 0]  # link row: r = x1 − x0 = (1, 0, 0)
    out = impact(masses, v, contact_row(3, 2, 0, (0, -1, 0)), e=1.0, keep_rows=[bar])
    assert np.allclose(out.velocities, [[0, -2, 0], [0, 0, 0], [0, 0, 0]], atol=1e-12)  # bar transmits nothing
    assert np.allclose(out.momentum_change, 0) and out.energy_change == pytest.approx(0, abs=1e-12)
    assert kinetic_energy(masses, out.velocities) == pytest.approx(2.0)


def test_plastic_impact_along_the_bar_moves_the_whole_barbell():
    masses = [1.0, 2.0, 1.0]
    v = np.array([[0, 0, 0], [0, 0, 0], [-3.0, 0, 0]])  # the ball comes along the bar onto point 1
    bar = np.zeros(9)
    bar[0:3], bar[3:6] = [-1.0, 0, 0], [1.0, 0, 0]
    out = impact(masses, v, contact_row(3, 2, 1, (-1, 0, 0)), e=0.0, keep_rows=[bar])
    assert np.allclose(out.velocities[:, 0], -0.75)  # 4 units of mass share the momentum −3
    assert out.energy_change == pytest.approx(0.5 * 4 * 0.75**2 - 4.5)


def test_collision_errors():
    with pytest.raises(CollisionError, match="not approaching"):
        ball_collision(1, 1, (0, 0, 0), (1, 0, 0), (1, 0, 0))
    with pytest.raises(CollisionError, match=r"\[0, 1\]"):
        ball_collision(1, 1, (1, 0, 0), (0, 0, 0), (1, 0, 0), e=1.5)
    with pytest.raises(CollisionError, match="not closing"):
        impact([1.0, 1.0], [[0, 0, 0], [1, 0, 0]], contact_row(2, 0, 1, (1, 0, 0)))
