"""Integrals kept in the equations and evaluated by quadrature in generated code (lagrange.codegen.quadrature).

Independent truth: exact integrals of polynomials; the closed forms of the uniform disc sliding and spinning on a
rough plane (Farkas, Bartels, Unger & Wolf 2003), themselves checked against the disc summed as rings whose
integral has a closed form in E (Wells Prob. 6.15); the reduced (v, ω) equations of that disc integrated with those
closed forms; scipy's adaptive quadrature (the reference backend); a kinetic energy written as an integral against
its closed form.
"""

import mpmath
import numpy as np
import pytest
import sympy as sp
from lagrange_problems._common import spinning_disc_friction
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import lagrange as lg
from lagrange import t
from lagrange.codegen.quadrature import DEFAULT_RULE, Rule

EPS = sp.Symbol("eps", positive=True)
_F, _T = (sp.lambdify(EPS, e, "mpmath") for e in spinning_disc_friction(EPS))


def F_CLOSED(eps):
    return float(_F(eps))


def T_CLOSED(eps):
    return float(_T(eps))


def _disc():
    """A uniform disc (radius a, mass m) sliding and spinning, friction f per unit area: μN = fπa²."""
    x, y, th = lg.coordinates("x y theta")
    m, a, f = lg.parameters("m a f")
    r, al = sp.symbols("r alpha", real=True)
    xd, yd, thd = x.diff(t), y.diff(t), th.diff(t)
    speed = sp.sqrt((xd - thd * r * sp.sin(th + al)) ** 2 + (yd + thd * r * sp.cos(th + al)) ** 2)
    P = -f * lg.Quadrature(speed * r, (r, 0, a), (al, 0, 2 * sp.pi))
    return lg.System([x, y, th], T=m * (xd**2 + yd**2) / 2 + m * a**2 / 4 * thd**2, P=P, name="disc"), (x, y, th)


DISC, (X, Y, TH) = _disc()
UNIT = {"m": 1.0, "a": 1.0, "f": 1 / np.pi}  # μN = 1, I = 1/2


# ----- the rule ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("rule", [Rule(1, 1), Rule(5, 1), Rule(8, 3), Rule(16, 2)])
def test_rule_integrates_polynomials_exactly_up_to_its_degree(rule):
    xi, wi = (np.array(v) for v in rule.nodes())
    assert len(xi) == rule.size and sum(wi) == pytest.approx(2.0, rel=1e-15)
    for k in range(2 * rule.order):  # exact through degree 2·order − 1 on every panel
        exact = (1 - (-1) ** (k + 1)) / (k + 1)
        assert np.dot(wi, xi**k) == pytest.approx(exact, abs=1e-14)
    if rule.panels == 1:  # and not beyond: x^(2·order) is not integrated exactly by one panel
        k = 2 * rule.order
        assert abs(np.dot(wi, xi**k) - 2 / (k + 1)) > 1e-6


@pytest.mark.parametrize("bad", [dict(order=0), dict(order=65), dict(panels=0), dict(panels=2.0), dict(order=True)])
def test_rule_refuses_values_out_of_range(bad):
    with pytest.raises(lg.OptionError, match="quadrature"):
        Rule(**bad)


# ----- the closed forms used as truth ---------------------------------------------------------------------------
def test_closed_forms_match_the_disc_summed_as_rings():
    """A ring of radius ρ: ∫₀^{2π}|V + ω×ρ| dα = 4(V + ωρ) E(4Vωρ/(V + ωρ)²) (Wells Prob. 6.15); the disc's
    P = −(μN/π) ∫₀¹ ρ·ring dρ. F = −∂P/∂V and T = −∂P/∂ω by 20-digit quadrature and differentiation."""
    mpmath.mp.dps = 20

    def P(V, w):
        ring = lambda r: 4 * r * (V + w * r) * mpmath.ellipe(4 * V * w * r / (V + w * r) ** 2)  # noqa: E731
        return -mpmath.quad(ring, [0, V / w, 1] if V < w else [0, 1]) / mpmath.pi

    for eps in (0.3, 1.7):
        F = -mpmath.re(mpmath.diff(lambda V: P(mpmath.re(V), mpmath.mpf(1)), eps))
        T = -mpmath.re(mpmath.diff(lambda w, e=eps: P(mpmath.mpf(e), mpmath.re(w)), 1))
        assert float(F) == pytest.approx(F_CLOSED(eps), rel=1e-12)
        assert float(T) == pytest.approx(T_CLOSED(eps), rel=1e-12)
    mpmath.mp.dps = 15


# ----- the disc: force and torque against the closed forms ------------------------------------------------------
def _force_and_torque(model, eps, heading, turned):
    """(F along −v, lateral F, torque) from the model at ω = 1, |v| = ε along ``heading``, the disc turned by
    ``turned`` (μN = 1, R = 1, m = 1, I = 1/2)."""
    c, s = np.cos(heading), np.sin(heading)
    acc = np.asarray(model.rhs(0.0, np.array([0.0, 0.0, turned, eps * c, eps * s, 1.0]), model._pcall))
    return -(acc[3] * c + acc[4] * s), acc[4] * c - acc[3] * s, -acc[5] / 2


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_disc_friction_agrees_with_the_published_closed_forms(backend):
    """Default rule: within 2e-4 relative with the instantaneous centre inside the disc (ε < 1: a kink of |v|
    inside the domain; measured 6e-5, benchmarks/results/quadrature.md), 1e-7 outside (measured 8e-9); a lateral
    force (by symmetry the friction opposes v) within 1e-3 of F inside (measured 6e-4) and 1e-7 outside. A finer
    rule is closer."""
    model = DISC.compile(UNIT, backend=backend)
    for eps, tol, side in ((0.2, 2e-4, 1e-3), (0.653, 2e-4, 1e-3), (0.9, 2e-4, 1e-3), (1.5, 1e-7, 1e-7),
                           (3.0, 1e-7, 1e-7)):
        F, lateral, T = _force_and_torque(model, eps, heading=0.4, turned=1.1)
        assert F == pytest.approx(F_CLOSED(eps), rel=tol) and T == pytest.approx(T_CLOSED(eps), rel=tol)
        assert abs(lateral) < side * F
    if backend == "numba":  # (one compiled module per rule: the finer rule is checked in python)
        return
    fine = DISC.compile(UNIT, backend=backend, quadrature=Rule(16, 8))
    F, _, T = _force_and_torque(fine, 0.4, heading=0.4, turned=1.1)
    assert F == pytest.approx(F_CLOSED(0.4), rel=1e-5) and T == pytest.approx(T_CLOSED(0.4), rel=1e-5)
    F, _, T = _force_and_torque(fine, 3.0, heading=0.4, turned=1.1)
    assert F == pytest.approx(F_CLOSED(3.0), rel=1e-12) and T == pytest.approx(T_CLOSED(3.0), rel=1e-12)


def test_a_coarse_rule_is_measurably_wrong():
    """The check can fail: one panel of 4 points misses the closed form by more than 1e-2 inside."""
    coarse = DISC.compile(UNIT, quadrature=Rule(4, 1))
    F, _, T = _force_and_torque(coarse, 0.3, heading=0.4, turned=1.1)
    assert max(abs(F / F_CLOSED(0.3) - 1), abs(T / T_CLOSED(0.3) - 1)) > 1e-2


def test_backends_agree_with_scipy_adaptive_quadrature():
    """python against the reference backend (scipy's nquad of the same integrals) where the integrand is smooth
    (ε = 3, the instantaneous centre outside the disc), with a rule fine enough for round-off there; numba (loops)
    against python (numpy arrays) with the same rule, also with the centre inside."""
    y0 = np.array([0.2, -0.1, 0.7, 2.4, 1.8, 1.0])  # |v| = 3, ω = 1
    ref = DISC.compile(UNIT, backend="reference")
    model = DISC.compile(UNIT, backend="python", quadrature=Rule(16, 8))
    assert np.allclose(model.rhs(0.0, y0, model._pcall), ref.rhs(0.0, y0, ref._pcall), rtol=1e-9, atol=1e-12)
    py, nb = DISC.compile(UNIT, backend="python"), DISC.compile(UNIT, backend="numba")
    for y in (y0, np.array([0.2, -0.1, 0.7, 0.24, 0.18, 1.0])):
        assert np.allclose(py.rhs(0.0, y, py._pcall), nb.rhs(0.0, y, nb._pcall), rtol=1e-13, atol=1e-15)


# ----- the disc stops sliding and spinning together -------------------------------------------------------------
def test_disc_stops_sliding_and_spinning_at_the_same_instant():
    """Farkas et al. (2003): v/(ωR) tends to the root ε* ≈ 0.653 of 𝓕(ε) = 2ε𝓣(ε) (I = mR²/2) and both motions stop
    together. The full (x, y, θ) model against the reduced equations v̇ = −μg𝓕(ε), ω̇ = −2μg𝓣(ε)/R integrated with
    the closed forms, from ε = 2 and from ε = 0.3, until the speed has fallen to 1e-3 of its start."""
    eps_star = brentq(lambda e: F_CLOSED(e) - 2 * e * T_CLOSED(e), 0.3, 0.9)
    assert eps_star == pytest.approx(0.653, abs=1e-3)
    for v0, w0 in ((1.0, 0.5), (0.3, 1.0)):
        def reduced(_, z):
            e = z[0] / z[1]
            return [-F_CLOSED(e), -2 * T_CLOSED(e)]

        def stop(_, z, level=1e-8 * v0):
            return z[0] - level

        stop.terminal = True
        red = solve_ivp(reduced, (0, 10), [v0, w0], events=stop, rtol=1e-12, atol=1e-16, dense_output=True)
        assert red.status == 1 and red.y[0, -1] / red.y[1, -1] == pytest.approx(eps_star, rel=1e-3)
        t_end = red.t[np.argmax(red.y[0] < 1e-3 * v0)]  # the full model runs until v = 1e-3 v0
        tr = DISC.simulate(t_end, {X: 0, Y: 0, TH: 0, "x_dot": v0 * 0.6, "y_dot": v0 * 0.8, "theta_dot": w0},
                           UNIT, method="DOP853", rtol=1e-10, atol=1e-13)
        v = np.hypot(tr.y[:, 3], tr.y[:, 4])
        w = tr.y[:, 5]
        zr = red.sol(tr.t)
        assert np.allclose(v, zr[0], rtol=0, atol=1e-3 * v0) and np.allclose(w, zr[1], rtol=0, atol=1e-3 * w0)
        # at the end both are small and their ratio follows the reduced one towards ε*: neither stops first
        assert v[-1] < 3e-3 * v0 and w[-1] < 1e-2 * w0
        assert v[-1] / w[-1] == pytest.approx(zr[0, -1] / zr[1, -1], rel=2e-2)
        assert v[-1] / w[-1] == pytest.approx(eps_star, rel=5e-2)
        # the heading does not turn (no lateral force): the disc slides along a straight line
        assert np.allclose(tr.y[:, 3] * 0.8 - tr.y[:, 4] * 0.6, 0.0, atol=1e-4 * v0)


# ----- what the equations say, and who refuses them -------------------------------------------------------------
def test_equations_keep_the_integral_in_wells_form_and_are_marked():
    eqs = DISC.derived
    assert eqs.has_quadrature
    assert all(e.has(sp.Integral) for e in eqs.forcing)
    printed = DISC.equations()
    assert all(eq.has(sp.Integral) for eq in printed)
    assert not lg.System([X], T=X.diff(t) ** 2 / 2, V=X**2 / 2).derived.has_quadrature


def test_taylor_and_heyoka_refuse_and_auto_does_not_offer_taylor():
    state = {X: 0, Y: 0, TH: 0, "x_dot": 1.0, "y_dot": 0.0, "theta_dot": 2.0}
    with pytest.raises(lg.LagrangeError, match="quadrature") as info:
        DISC.simulate(0.1, state, UNIT, method="taylor")
    assert isinstance(info.value, TypeError)
    from lagrange.codegen.heyoka_expr import heyoka_available

    if heyoka_available():
        with pytest.raises(lg.LagrangeError, match="quadrature"):
            DISC.simulate(0.1, state, UNIT, method="heyoka")
    tr = DISC.simulate(0.1, state, UNIT, method="auto", rtol=1e-12)  # smooth and tight: Taylor if it could
    assert not tr.method.lower().startswith("taylor")  # the method run, and auto says why Taylor was excluded
    assert "not analytic (Quadrature)" in tr.method


def test_power_balance_closes_with_quadrature():
    """h − h₀ − ∫ dh/dt: the work of the friction integrals, computed by the same rule, closes the balance."""
    state = {X: 0, Y: 0, TH: 0, "x_dot": 0.4, "y_dot": 0.1, "theta_dot": 2.0}
    tr = DISC.simulate(0.5, state, UNIT, method="DOP853", rtol=1e-10, atol=1e-12)
    assert tr.energy_error() < 1e-8
    assert tr.energy[-1] < tr.energy[0]  # friction dissipates


def test_kinetic_energy_as_an_integral_gives_the_mass_matrix_by_quadrature():
    """A uniform rod (density λ, length l) turning about one end on a spring: T = ½∫₀ˡ λ r² θ̇² dr kept as a
    Quadrature; the mass matrix is the integral λl³/3 (python mass() and the rhs), the motion that of the closed
    form."""
    th = lg.coordinates("theta")
    lam, l, k = lg.parameters("lambda l k")
    r = sp.Symbol("r", real=True)
    s = lg.System([th], T=lg.Quadrature(lam * r**2 * th.diff(t) ** 2 / 2, (r, 0, l)), V=k * th**2 / 2)
    assert s.derived.mass_matrix[0, 0].has(sp.Integral)
    p = {"lambda": 3.0, "l": 2.0, "k": 5.0}
    model = s.compile(p)
    assert model.mass_matrix(0.0, [0.1, 0.2])[0, 0] == pytest.approx(3.0 * 8 / 3, rel=1e-14)
    tr = s.simulate(1.0, {th: 0.1, "theta_dot": 0.0}, p, rtol=1e-11, atol=1e-13)
    assert tr.y[-1, 0] == pytest.approx(0.1 * np.cos(np.sqrt(5.0 / 8.0)), abs=1e-9)
    with pytest.raises(lg.LagrangeError, match="quadrature"):  # H is built symbolically from T: refused by name
        s.simulate(1.0, {th: 0.1, "theta_dot": 0.0}, p, method="gl4", step=0.01)


def test_nested_integrals_are_one_multiple_integral_and_an_integral_inside_an_integrand_is_refused():
    x = lg.coordinates("x")
    u, w = sp.symbols("u w", real=True)
    xd = x.diff(t)
    nested = lg.System([x], T=xd**2 / 2,
                       P=-sp.Integral(lg.Quadrature(sp.sqrt(xd**2 + u**2 + w**2), (u, 0, 1)), (w, 0, 1)))
    (integral,) = nested.P.atoms(sp.Integral)
    assert len(integral.limits) == 2
    with pytest.raises(lg.DeclarationError, match="one multiple integral"):
        lg.System([x], T=xd**2 / 2,
                  P=-lg.Quadrature(xd * lg.Quadrature(sp.sqrt(xd**2 + u**2 + w**2), (u, 0, 1)) + w, (w, 0, 1)))


def test_default_rule_is_the_documented_one():
    assert (DEFAULT_RULE.order, DEFAULT_RULE.panels) == (8, 8)


def test_structural_derivation_is_not_chosen_for_an_integral_in_P():
    """From 6 coordinates "auto" derives structurally, which has no quadrature: an integral in P keeps the expanded
    derivation (and asking for structural is refused by name)."""
    qs = lg.coordinates("q1 q2 q3 q4 q5 q6")
    r = sp.Symbol("r", real=True)
    bodies = [lg.Particle(1, (q,)) for q in qs]
    plain = lg.System(list(qs), bodies=bodies)
    assert plain.derivation == "structural"
    P = -lg.Quadrature(sp.sqrt(qs[0].diff(t) ** 2 + r**2), (r, 0, 1))
    assert lg.System(list(qs), bodies=bodies, P=P).derivation == "expanded"
    with pytest.raises(lg.DeclarationError, match="structural.*integral"):
        lg.System(list(qs), bodies=bodies, P=P, derivation="structural")


def test_generated_jacobian_differentiates_under_the_integral_sign():
    """The Jacobian implicit methods use (∂f/∂y under the integral sign, by the same rule) against central
    differences of the right-hand side, where the integrand is smooth (ε = 3)."""
    model = DISC.compile(UNIT)
    y0 = np.array([0.2, -0.1, 0.7, 2.4, 1.8, 1.0])
    J = model.jacobian(0.0, y0)
    h = 1e-6
    D = np.column_stack([(np.asarray(model.rhs(0.0, y0 + h * e, model._pcall))
                          - np.asarray(model.rhs(0.0, y0 - h * e, model._pcall))) / (2 * h) for e in np.eye(6)])
    assert np.allclose(J, D, rtol=1e-6, atol=1e-8)
    assert np.abs(J[3:, 3:]).max() > 1e-2  # the friction does depend on the velocities
    tr = DISC.simulate(0.3, {X: 0, Y: 0, TH: 0, "x_dot": 2.4, "y_dot": 1.8, "theta_dot": 1.0}, UNIT, method="Radau",
                       rtol=1e-9, atol=1e-12)
    ref = DISC.simulate(0.3, {X: 0, Y: 0, TH: 0, "x_dot": 2.4, "y_dot": 1.8, "theta_dot": 1.0}, UNIT,
                        method="DOP853", rtol=1e-11, atol=1e-13)
    assert np.allclose(tr.y[-1], ref.y[-1], rtol=1e-7, atol=1e-9)


def test_an_integration_variable_named_like_a_coordinate_is_refused():
    """The derivation writes x(t) and ẋ as plain symbols x and x_dot: an integration variable of that name would
    capture them (a silently wrong force); it is refused by name. Another name is accepted."""
    x = lg.coordinates("x")
    xd = x.diff(t)
    for name in ("x", "x_dot", "t"):
        u = sp.Symbol(name, real=True)
        with pytest.raises(lg.DeclarationError, match="name of a coordinate"):
            lg.System([x], T=xd**2 / 2, P=-lg.Quadrature(sp.sqrt(xd**2 + u**2), (u, 0, 1)))
    u = sp.Symbol("u", real=True)
    assert lg.System([x], T=xd**2 / 2, P=-lg.Quadrature(sp.sqrt(xd**2 + u**2), (u, 0, 1))).P.has(sp.Integral)


def test_a_rod_that_does_not_turn_is_integrated_without_a_division_by_zero():
    """The kink of |v| along a rod is at −B/(2A) with A = θ̇²: at θ̇ = 0 there is none, and generated code must not
    divide by zero (python arrays, python loops and numba alike): F_x = −f l ẋ/|v| exactly."""
    x, y, th = lg.coordinates("x y theta")
    f, l = lg.parameters("f l")
    r = sp.Symbol("r", real=True)
    xd, yd, thd = x.diff(t), y.diff(t), th.diff(t)
    speed = sp.sqrt((xd - r * thd * sp.sin(th)) ** 2 + (yd + r * thd * sp.cos(th)) ** 2)
    T = (xd**2 + yd**2 + thd**2) / 2
    smooth = lg.System([x, y, th], T=T, P=-f * lg.Quadrature(speed, (r, 0, l)))
    # Γ(1 + sin² + cos²) = 1, which numpy does not apply elementwise: the loop flavour in python
    looped = lg.System([x, y, th], T=T, P=-f * lg.Quadrature(speed * sp.gamma(1 + sp.sin(r) ** 2 + sp.cos(r) ** 2),
                                                              (r, 0, l)))
    y0 = np.array([0.0, 0.0, 0.4, 0.6, 0.8, 0.0])
    for s in (smooth, looped):
        for backend in ("python", "numba"):
            model = s.compile({"f": 0.5, "l": 2.0}, backend=backend)
            acc = np.asarray(model.rhs(0.0, y0, model._pcall))
            assert acc[3] == pytest.approx(-0.5 * 2.0 * 0.6, rel=1e-13) and acc[4] == pytest.approx(-0.8, rel=1e-13)
