"""Constraints: declarations, multipliers and their sign, elimination, drift control, contact, friction."""

import warnings

import numpy as np
import pytest
import sympy as sp

from lagrange import (
    DeclarationError,
    Differential,
    Holonomic,
    InitialConditionError,
    InitialStateChangedWarning,
    IntegrableConstraintWarning,
    Nonholonomic,
    Particle,
    Rough,
    SingularMassMatrixError,
    System,
    coordinates,
    eliminate,
    parameters,
    t,
)
from lagrange.simplification import is_zero


def cartesian_pendulum():
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    return s, x, y, (m, g, l)


def polar_pendulum():
    th = coordinates("theta")
    m, g, l = parameters("m g l")
    return System([th], bodies=[Particle(m, (l * sp.sin(th), -l * sp.cos(th)))], V=-m * g * l * sp.cos(th)), th


PARAMS = {"m": 1.0, "g": 9.81, "l": 1.0}


class TestDeclarations:
    def test_classification_and_printing(self):
        s, x, y, (m, g, l) = cartesian_pendulum()
        (spec,) = s.constraints
        assert spec.kind == "holonomic"
        eqs = s.equations()
        assert len(eqs) == 3  # two Lagrange equations with λ, plus the constraint
        lam = s.derived.multipliers[0]
        assert is_zero(eqs[0].rhs - lam * x / sp.sqrt(x**2 + y**2))
        assert is_zero(eqs[2].lhs - (sp.sqrt(x**2 + y**2) - l))
        assert "λ" in str(s) and "constraint string" in str(s)

    def test_differential_form_equals_velocity_form(self):
        x, y, th = coordinates("x y theta")
        m, I = parameters("m I")
        T = m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2 + I * th.diff(t) ** 2 / 2
        a = System([x, y, th], T=T, constraints=[Nonholonomic(y.diff(t) * sp.cos(th) - x.diff(t) * sp.sin(th))])
        b = System([x, y, th], T=T, constraints=[Differential({y: sp.cos(th), x: -sp.sin(th)})])
        assert a.derived.constraint_matrix == b.derived.constraint_matrix

    def test_errors_name_the_constraint(self):
        x, y = coordinates("x y")
        m = parameters("m")
        with pytest.raises(DeclarationError) as exc:
            System([x, y], bodies=[Particle(m, (x, y))],
                   constraints=[Holonomic(x.diff(t), "bad1"), x.diff(t) ** 2 + y, x.diff(t, 2),
                                Nonholonomic(x - y, "bad4")])
        msg = "\n".join(exc.value.problems)
        assert "bad1 is declared holonomic but contains velocities" in msg
        assert "not linear in the velocities" in msg
        assert "acceleration" in msg
        assert "bad4 is declared non-holonomic but has no velocities" in msg

    def test_integrable_differential_constraint_is_reported(self):
        x, y, z = coordinates("x y z")
        m = parameters("m")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            s = System([x, y, z], bodies=[Particle(m, (x, y, z))], constraints=[y * x.diff(t) + x * y.diff(t)])
            System([x, y, z], bodies=[Particle(m, (x, y, z))], constraints=[z.diff(t) - y * x.diff(t)])
        found = [w for w in caught if issubclass(w.category, IntegrableConstraintWarning)]
        assert len(found) == 1 and "integrable" in str(found[0].message)  # d(xy) = 0 is; dz − y dx is not
        assert s.constraints[0].integrable

    def test_frobenius_numeric_decides_non_integrable_forms_and_defers_integrable_ones(self):
        from lagrange.model.constraints import _frobenius_numeric, is_integrable
        from lagrange.model.coordinates import position_symbol

        x, y, th, z = coordinates("x y theta z")
        r, k = parameters("r k")
        syms = [position_symbol(q) for q in (x, y, th, z)] + [t]

        def numeric(coeffs, a_t=0):
            a = [sp.sympify(c).subs({q: position_symbol(q) for q in (x, y, th, z)}) for c in coeffs] + [sp.sympify(a_t)]
            return _frobenius_numeric(a, syms, list(range(len(syms))))

        # knife edge dx cosθ + dy sinθ − r dz... rolling is not integrable: the numeric test alone says so
        rolling = [sp.cos(th), sp.sin(th), 0, -r]
        assert numeric(rolling) is False and not is_integrable(rolling, 0, [x, y, th, z])
        # an exact differential times an integrating factor, with messy coefficients: integrable; the numeric
        # test cannot prove that (it only finds zeros) and leaves it to the symbolic proof
        F = x * y + sp.sin(z) * x + k * th**2
        factor = sp.exp(y) / (1 + x**2)
        exact = [factor * sp.diff(F, q) for q in (x, y, th, z)]
        assert numeric(exact) is None and is_integrable(exact, 0, [x, y, th, z])
        # explicit time: dx − t dy is not integrable in (x, y, t)
        assert numeric([1, -t, 0, 0]) is False and not is_integrable([1, -t, 0, 0], 0, [x, y, th, z])
        # the moving constraint dx − v dt (v constant) is integrable (x − v t = const)
        assert is_integrable([1, 0, 0, 0], -k, [x, y, th, z])


class TestMultipliers:
    def test_cartesian_pendulum_matches_polar_and_tension(self):
        """λ of φ = r − l is the outward radial force: the string tension is −λ = m g cosθ + m l θ̇²."""
        s, x, y, _ = cartesian_pendulum()
        polar, th = polar_pendulum()
        th0 = 0.7
        a = s.simulate(6, {x: np.sin(th0), y: -np.cos(th0), x.diff(t): 0, y.diff(t): 0}, PARAMS)
        b = polar.simulate(6, {th: th0, th.diff(t): 0}, PARAMS)
        assert np.max(np.abs(np.arctan2(a[x], -a[y]) - b[th])) < 1e-7
        tension = 9.81 * np.cos(b[th]) + b[th.diff(t)] ** 2
        assert np.max(np.abs(-a.multiplier("string") - tension)) < 1e-6
        assert a.energy_error() < 1e-9

    def test_elimination_and_multipliers_agree(self):
        """Wells Ex. 3.2: bead on the wire y = b x², both formulations."""
        x, y = coordinates("x y")
        m, g, b = parameters("m g b")
        s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y, constraints=[Holonomic(y - b * x**2, "wire")])
        reduced = eliminate(s, [y])
        assert reduced.coordinates == (x,) and not reduced.constraints
        (eq,) = reduced.equations()
        book = m * x.diff(t, 2) * (1 + 4 * b**2 * x**2) + 4 * m * b**2 * x * x.diff(t) ** 2 + 2 * m * g * b * x
        assert is_zero(eq.lhs - eq.rhs - book)
        p = {"m": 1, "g": 9.81, "b": 0.5}
        full = s.simulate(8, {x: 1, y: 0.5, x.diff(t): 0, y.diff(t): 0}, p)
        red = reduced.simulate(8, {x: 1, x.diff(t): 0}, p)
        assert np.max(np.abs(full[x] - red[x])) < 1e-7

    def test_elimination_carries_generalized_forces(self):
        x, y = coordinates("x y")
        m, F = parameters("m F")
        s = System([x, y], bodies=[Particle(m, (x, y))], forces={y: F}, constraints=[y - x**2])
        red = eliminate(s, {y: x**2})
        assert is_zero(red.forces[x] - 2 * F * x)
        with pytest.raises(DeclarationError, match="2 solutions"):
            eliminate(System([x, y], bodies=[Particle(m, (x, y))], constraints=[x**2 + y**2 - 1]), [y])

    def test_moving_constraint_force_and_power(self):
        """Wells Ex. 3.5: bead on a rod turning at constant ω; the rod's normal force is N = 2 m ω ṙ and it
        does work (the power balance includes it)."""
        x, y = coordinates("x y")
        m, w = parameters("m omega")
        rod = y * sp.cos(w * t) - x * sp.sin(w * t)  # distance from the rod, along its normal
        s = System([x, y], bodies=[Particle(m, (x, y))], constraints=[Holonomic(rod, "rod")])
        sol = s.simulate(1.5, {x: 0.3, y: 0, x.diff(t): 0.1, y.diff(t): 0.6}, {"m": 2.0, "omega": 2.0})
        r = np.hypot(sol[x], sol[y])
        rdot = (sol[x] * sol[x.diff(t)] + sol[y] * sol[y.diff(t)]) / r
        assert np.max(np.abs(sol.multiplier("rod") - 2 * 2.0 * 2.0 * rdot)) < 1e-6
        assert sol.energy_error() < 1e-8  # h changes by exactly the work of the moving constraint


class TestDrift:
    def test_projection_bounds_drift_and_plain_index1_drifts(self):
        s, x, y, _ = cartesian_pendulum()
        ic = {x: 1.0, y: 0.0, x.diff(t): 0.0, y.diff(t): 0.0}
        opts = dict(rtol=1e-5, atol=1e-7, n_points=201)
        proj = s.simulate(100, ic, PARAMS, **opts)
        plain = s.simulate(100, ic, PARAMS, stabilization="none", **opts)
        baum = s.simulate(100, ic, PARAMS, stabilization="baumgarte", **opts)
        assert proj.max_constraint_violation() < 1e-10
        assert plain.max_constraint_violation() > 1e3 * proj.max_constraint_violation()
        assert baum.max_constraint_violation() < 0.1 * plain.max_constraint_violation()  # decays, not round-off
        early = np.max(plain.constraint_violation["position"][:20])
        late = np.max(plain.constraint_violation["position"][-20:])
        assert late > 10 * early  # it grows without stabilization

    def test_bdf_falls_back_to_baumgarte(self):
        s, x, y, _ = cartesian_pendulum()
        sol = s.simulate(2, {x: 1.0, y: 0.0, x.diff(t): 0.0, y.diff(t): 0.0}, PARAMS, method="BDF")
        assert "Baumgarte" in sol.method and sol.max_constraint_violation() < 1e-4

    def test_initial_conditions_projected_or_rejected(self):
        s, x, y, _ = cartesian_pendulum()
        bad = {x: 1.05, y: 0.0, x.diff(t): 0.1, y.diff(t): 0.0}
        with pytest.warns(InitialStateChangedWarning, match="x 1.05 → 1, x_dot 0.1 → 0"):  # never silently
            sol = s.simulate(0.5, bad, PARAMS)
        assert abs(np.hypot(sol[x][0], sol[y][0]) - 1.0) < 1e-12
        pos, vel = sol.initial_constraint_violation["string"]
        assert pos == pytest.approx(0.05) and vel == pytest.approx(0.1)
        with pytest.raises(InitialConditionError, match="string: φ = 0.05"):
            s.simulate(0.5, bad, PARAMS, project_initial=False)

    def test_redundant_constraints_are_named(self):
        x, y = coordinates("x y")
        m = parameters("m")
        s = System([x, y], bodies=[Particle(m, (x, y))],
                   constraints=[Holonomic(x - y, "c1"), Holonomic(2 * x - 2 * y, "c2")])
        with pytest.raises(SingularMassMatrixError, match="c1, c2 are dependent"):
            s.simulate(1, {x: 0, y: 0, x.diff(t): 1, y.diff(t): 1}, {"m": 1})


def test_knife_edge_nonholonomic_closed_form():
    """A skate: ẏ cosθ − ẋ sinθ = 0, no forces: θ̇ constant and the contact point runs on a circle of
    radius v/θ̇."""
    x, y, th = coordinates("x y theta")
    m, I = parameters("m I")
    T = m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2 + I * th.diff(t) ** 2 / 2
    s = System([x, y, th], T=T, constraints=[Nonholonomic(y.diff(t) * sp.cos(th) - x.diff(t) * sp.sin(th), "blade")])
    v, w = 1.5, 0.8
    sol = s.simulate(10, {x: 0, y: 0, th: 0, x.diff(t): v, y.diff(t): 0, th.diff(t): w}, {"m": 1, "I": 0.3})
    assert np.allclose(sol[th], w * sol.t, atol=1e-8)
    assert np.allclose(sol[x], v / w * np.sin(w * sol.t), atol=1e-7)
    assert np.allclose(sol[y], v / w * (1 - np.cos(w * sol.t)), atol=1e-7)
    assert sol.max_constraint_violation() < 1e-10


def test_particle_leaves_a_sphere_at_the_book_angle():
    """Wells P12.7: sliding from the top of a smooth sphere; contact is lost when
    cosθ = (2g + r θ̇0²)/(3g). The unilateral constraint ends the run with an event there."""
    r_, th, ph = coordinates("r theta phi")
    m, g, R = parameters("m g R")
    pos = (r_ * sp.sin(th) * sp.cos(ph), r_ * sp.sin(th) * sp.sin(ph), r_ * sp.cos(th))
    s = System([r_, th, ph], bodies=[Particle(m, pos)], V=m * g * r_ * sp.cos(th),
               constraints=[Holonomic(r_ - R, "surface", unilateral=True)])
    w0, Rv, gv = 0.5, 2.0, 9.81
    sol = s.simulate(5, {r_: Rv, th: 0.01, ph: 0, r_.diff(t): 0, th.diff(t): w0, ph.diff(t): 0},
                     {"m": 1, "g": gv, "R": Rv})
    assert "Contact lost" in sol.message
    (t_off,) = sol.t_events[-1]
    y_off = sol.y_events[-1][0]
    # energy from the actual start θ=0.01: cosθ_off = (2g cosθ0 + R θ̇0²)/(3g)
    expected = (2 * gv * np.cos(0.01) + Rv * w0**2) / (3 * gv)
    assert np.cos(y_off[1]) == pytest.approx(expected, rel=1e-8)


def test_rough_wire_matches_wells_ex_12_9():
    """Wells Ex. 12.9: bead sliding down a rough parabolic wire; friction μ|N| opposes the sliding.
    Book: m ẍ(1 + 4b²x²) + 4mb²xẋ² = 2μbmẋ² + μmg − 2bxmg while it slides down (x > 0, ẋ < 0)."""
    x, y = coordinates("x y")
    m, g, b, mu = parameters("m g b mu")
    nrm = sp.sqrt(1 + 4 * b**2 * x**2)
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Rough(y - b * x**2, mu, (x.diff(t) + 2 * b * x * y.diff(t)) / nrm, "wire", normal=nrm)])
    p = {"m": 1.0, "g": 9.81, "b": 0.5, "mu": 0.2}
    sol = s.simulate(3, {x: 2.0, y: 2.0, x.diff(t): 0.0, y.diff(t): 0.0}, p)
    X, Xd, Xdd = sol[x], sol[x.diff(t)], sol[x.diff(t, 2)]
    down = X > 0
    lhs = Xdd * (1 + 4 * 0.25 * X**2) + 4 * 0.25 * X * Xd**2
    rhs = 2 * 0.2 * 0.5 * Xd**2 + 0.2 * 9.81 - 2 * 0.5 * X * 9.81
    assert np.max(np.abs(lhs - rhs)[down]) < 1e-8
    assert "Sliding stopped" in sol.message  # the bead stops on the far side: sticking is not modelled
    assert sol.energy_error() < 1e-7  # friction work is in the balance
    held = s.simulate(3, {x: 0.2, y: 0.02, x.diff(t): 0, y.diff(t): 0}, {**p, "mu": 0.5})
    assert "friction holds it" in held.message and len(held.t) == 1
