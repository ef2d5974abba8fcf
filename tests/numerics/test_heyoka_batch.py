"""integrate_ensemble(method="heyoka"): the members through heyoka's taylor_adaptive_batch (SIMD lanes).

Truth: the default ensemble path (scipy's DOP853 control per member) at tight tolerance, with the parameters
varying per member, a member count that is not a multiple of the batch size (the padded last group), and
a member that fails (non-finite state) without spoiling the others; the single-member heyoka run.
"""

import numpy as np
import pytest
import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.errors import LagrangeError
from lagrange.examples import n_link_pendulum
from lagrange.sweep import integrate_ensemble

hy = pytest.importorskip("heyoka")
from lagrange.integrate import heyoka_batch  # noqa: E402

TIGHT = {"rtol": 1e-12, "atol": 1e-12}


@pytest.fixture(scope="module")
def chain():
    return n_link_pendulum(2).compile({"g": 9.81})


def _members(k, seed=1):
    rng = np.random.default_rng(seed)
    Y0 = np.hstack([rng.uniform(-1, 1, (k, 2)), rng.uniform(-0.5, 0.5, (k, 2))])
    return Y0, rng.uniform(5.0, 15.0, (k, 1))  # g per member


def test_batch_matches_the_default_ensemble_with_parameters_per_member(chain):
    k = 2 * heyoka_batch.batch_size() + 1  # a padded last group
    Y0, P = _members(k)
    t_eval = np.linspace(0.5, 3.0, 6)  # not starting at t0
    mine = integrate_ensemble(chain, 3.0, Y0, P, method="heyoka", t_eval=t_eval, **TIGHT)
    ref = integrate_ensemble(chain, 3.0, Y0, P, method="DOP853", t_eval=t_eval, rtol=1e-12, atol=1e-14)
    assert mine.method.startswith("heyoka (taylor_adaptive_batch") and mine.success.all()
    assert mine.y.shape == ref.y.shape == (k, 6, 4) and np.array_equal(mine.t, t_eval)
    assert np.max(np.abs(mine.y - ref.y)) < 1e-9
    assert np.all(mine.nsteps > 0) and np.all(mine.nfev >= mine.nsteps)
    one = n_link_pendulum(2).simulate(3.0, dict(zip(["q1", "q2", "q1_dot", "q2_dot"], Y0[-1])),
                                      {"g": float(P[-1, 0])}, method="heyoka", t_eval=t_eval, **TIGHT)
    assert np.max(np.abs(mine.y[-1] - one.y)) < 1e-11  # the padded group's real member, as a lone run


def test_a_failing_member_does_not_spoil_its_batch(chain):
    Y0, P = _members(5, seed=2)
    Y0[1, 2] = np.inf
    mine = integrate_ensemble(chain, 2.0, Y0, P, method="heyoka", n_points=5, **TIGHT)
    ref = integrate_ensemble(chain, 2.0, Y0, P, method="DOP853", n_points=5, rtol=1e-12, atol=1e-14)
    assert list(mine.status) == [0, -1, 0, 0, 0] and "heyoka" in mine.messages[1]
    good = [0, 2, 3, 4]
    assert np.max(np.abs(mine.y[good] - ref.y[good])) < 1e-9 and np.isnan(mine.y[1, 1:]).all()


def test_what_heyoka_cannot_integrate_is_refused_by_name():
    x, y = coordinates("x y")
    mu = parameters("mu")
    block = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2, forces={x: -mu * sp.sign(x.diff(t))})
    with pytest.raises(LagrangeError, match="sign"):
        integrate_ensemble(block.compile({"mu": 0.1}), 1.0, [[1.0, 0.0]], method="heyoka")
    ring = System([x, y], T=(x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=y, constraints=[x**2 + y**2 - 1])
    with pytest.raises(TypeError, match="unconstrained"):  # the ensemble's own check, before any method
        integrate_ensemble(ring.compile({}), 1.0, [[1.0, 0.0, 0.0, 0.0]], method="heyoka")
    with pytest.raises(TypeError, match="heyoka"):
        integrate_ensemble(block.compile({"mu": 0.1}), 1.0, [[1.0, 0.0]], method="Heyoka2")
