"""The structural derivation (lagrange/derive/structural.py, codegen/structural_source.py) against the expanded one.

Independent truths: the expanded derivation (d/dt ∂T/∂q̇ − ∂T/∂q of the whole T, lagrange/derive/lagrange.py);
the structure's own M and f assembled symbolically here from its J, a, W, α, I and Q (so the derivation is
checked apart from the generated code); and the reference backend (plain lambdify + numpy.linalg.solve).
"""

from __future__ import annotations

import dataclasses
import math
import pickle

import numpy as np
import pytest
import sympy as sp

import lagrange
from lagrange import (
    EulerAngles,
    Force,
    Holonomic,
    Nonholonomic,
    Particle,
    RigidBody,
    RotationSequence,
    System,
    coordinates,
    inputs,
    parameters,
    rot_x,
    rot_z,
    t,
)
from lagrange.derive.structural import StructuralEquations
from lagrange.errors import DeclarationError, LagrangeError
from lagrange.examples import n_link_pendulum
from lagrange.model.frames import Frame


def _values(eqs, seed=0) -> dict:
    rng = np.random.default_rng(seed)
    return {s.name: float(rng.uniform(0.5, 1.5)) for s in eqs.parameters}


def _assembled(eqs: StructuralEquations):
    """M and f of the structure, assembled symbolically: Σ m JᵀJ + Σ WᵀIW and
    Q − Σ m Jᵀa − Σ Wᵀ(Iα + ω × Iω)."""
    n, s = eqs.n, eqs.structure
    qd = sp.Matrix(eqs.qd)
    M, f = sp.zeros(n, n), sp.Matrix(s.generalized_force)
    for p in s.points:
        J = sp.zeros(3, n)
        for (i, j), e in p.jacobian:
            J[i, j] = e
        M += p.mass * J.T * J
        f -= p.mass * J.T * sp.Matrix(p.acceleration_bias)
    for r in s.rotors:
        W = sp.zeros(3, n)
        for (i, j), e in r.jacobian:
            W[i, j] = e
        I, w = sp.Matrix(r.inertia), W * qd + sp.Matrix(r.omega_bias)
        M += W.T * I * W
        f -= W.T * (I * sp.Matrix(r.acceleration_bias) + w.cross(I * w))
    return M, f


def _point_values(eqs, values, rng):
    sub = {sp.Symbol(k, **s.assumptions0): v for k, v in values.items() for s in eqs.parameters if s.name == k}
    sub.update({s: float(rng.normal()) for s in (*eqs.q, *eqs.qd)})
    sub[t] = 0.37
    return sub


def _check_pair(make, *, n_states=3, seed=0, inputs_values=None, tol=1e-9):
    """Structural and expanded declarations of the same system: the structure's M and f equal the expanded ones at
    random states and parameters, and the generated code of both gives the same q̈ (and λ)."""
    structural, expanded = make("structural"), make("expanded")
    es, ee = structural.derived, expanded.derived
    assert isinstance(es, StructuralEquations) and not ee.is_structural
    assert [s.name for s in es.parameters] == [s.name for s in ee.parameters]
    assert es.inputs == ee.inputs and es.m == ee.m
    values = {**_values(ee, seed), **(inputs_values or {})}
    rng = np.random.default_rng(seed + 1)
    Ms, fs = _assembled(es)
    for _ in range(n_states):
        sub = _point_values(ee, values, rng)
        sub.update({u: values[u.name] for u in ee.inputs})
        Mv = np.array(Ms.xreplace(sub).evalf(), dtype=float)
        Me = np.array(ee.mass_matrix.xreplace(sub).evalf(), dtype=float)
        fv = np.array(fs.xreplace(sub).evalf(), dtype=float).ravel()
        fe = np.array(ee.forcing.xreplace(sub).evalf(), dtype=float).ravel()
        assert np.allclose(Mv, Me, rtol=tol, atol=tol * np.abs(Me).max())
        assert np.allclose(fv, fe, rtol=tol, atol=tol * max(1.0, np.abs(fe).max()))
    ms = structural.compile({k: v for k, v in values.items() if k in {s.name for s in es.numeric_parameters}})
    me = expanded.compile({k: v for k, v in values.items() if k in {s.name for s in ee.numeric_parameters}})
    ref = expanded.compile({k: v for k, v in values.items() if k in {s.name for s in ee.numeric_parameters}},
                           backend="reference")
    for _ in range(n_states):
        y = rng.normal(size=2 * es.n) * 0.5
        a = np.asarray(ms.dynamics(0.37, y, ms._pcall), dtype=float)
        b = np.asarray(me.dynamics(0.37, y, me._pcall), dtype=float)
        c = np.asarray(ref.dynamics(0.37, y, ref.params), dtype=float)
        scale = max(1.0, np.abs(b).max())
        assert np.abs(a - b).max() < tol * scale
        assert np.abs(a - c).max() < 1e3 * tol * scale
    return structural, expanded


def test_nlink_symbolic_masses_and_lengths():
    s, _ = _check_pair(lambda d: n_link_pendulum(3, symbolic=True, derivation=d))
    assert "_expanded" not in s.derived.__dict__  # compile read the structure only


def test_particle_in_rotating_translating_frame_explicit_t():
    def make(d):
        x, y = coordinates("x y")
        m, k, w, a = parameters("m k omega a")
        frame = Frame(origin=(a * sp.sin(w * t), 0, 0), rotation=rot_z(w * t))
        return System([x, y], bodies=[Particle(m, frame.point((x, y)))], V=k * (x**2 + y**2) / 2, derivation=d)

    s, _ = _check_pair(make)
    assert not s.derived.is_autonomous and not s.derived.is_conservative


def test_uniformly_rotating_frame_conserves_the_jacobi_integral():
    """In a frame turning at constant rate the explicit t cancels from T: conservative in both derivations, and
    the Jacobi integral of a run stays constant."""
    x, y = coordinates("x y")
    m, k, w = parameters("m k omega")

    def make(d):
        return System([x, y], bodies=[Particle(m, Frame(rotation=rot_z(w * t)).point((x, y)))],
                      V=k * (x**2 + y**2) / 2, derivation=d)

    s, _ = _check_pair(make)
    assert s.derived.is_conservative and s.derived.jacobi_rate == 0
    tr = s.simulate(3.0, {"x": 1.0, "y": 0.0, "x_dot": 0.0, "y_dot": 0.5}, {"m": 1.0, "k": 2.0, "omega": 0.7},
                    rtol=1e-11, atol=1e-12)
    h = tr.diagnostics["jacobi"]
    assert np.ptp(h) < 1e-8 * abs(h[0])


def test_heavy_top_euler_angles_with_centre_of_mass_offset():
    def make(d):
        psi, th, ph = coordinates("psi theta phi")
        m, g, l, A, C = parameters("m g l A C")
        top = RigidBody(m, (A, A, C), orientation=EulerAngles(psi, th, ph), com=(0, 0, l))
        return System([psi, th, ph], bodies=[top], V=m * g * top.centre_of_mass[2], derivation=d)

    s, _ = _check_pair(make)
    assert s.derived.is_conservative and s.derived.is_autonomous


def test_rigid_body_3d_full_tensor_moving_origin_and_torque():
    def make(d):
        x, y, a, b = coordinates("x y a b")
        m, I1, I2, I3, I12, w, tau = parameters("m I1 I2 I3 I12 w tau")
        tensor = sp.Matrix([[I1 + I2, I12 / 4, 0], [I12 / 4, I2 + I3, 0], [0, 0, I1 + I3]])
        body = RigidBody(m, tensor, origin=(x, y, sp.sin(w * t)), orientation=rot_z(a) * rot_x(b),
                         com=(sp.Rational(1, 10), 0, sp.Rational(1, 5)))
        return System([x, y, a, b], bodies=[body], forces=[lagrange.Torque(body, (0, tau, tau / 2))],
                      derivation=d)

    _check_pair(make)


def _disc(d):
    x, y, q1, q2, q3 = coordinates("x y q1 q2 q3")
    m, g, r = parameters("m g r")
    orientation = RotationSequence(("z", q1), ("x", q2), ("y", q3))
    lean = rot_z(q1) * rot_x(q2)
    centre = sp.Matrix([x, y, 0]) + r * lean * sp.Matrix([0, 0, 1])
    disc = RigidBody(m, (m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), origin=centre, orientation=orientation)
    omega = orientation.space_angular_velocity()
    v_contact = centre.diff(t) + omega.cross(-r * lean * sp.Matrix([0, 0, 1]))
    return System([x, y, q1, q2, q3], bodies=[disc], V=m * g * centre[2], derivation=d,
                  constraints=[Nonholonomic(v_contact[0], "roll x"), Nonholonomic(v_contact[1], "roll y")])


def test_rolling_disc_nonholonomic_multipliers():
    _check_pair(_disc, n_states=2)


def test_inputs_applied_forces_and_dissipation():
    def make(d):
        x, th = coordinates("x theta")
        m, M_, l, g, c, b = parameters("m M l g c b")
        u = inputs("u")
        cart = Particle(M_, (x, 0))
        bob = Particle(m, (x + l * sp.sin(th), -l * sp.cos(th)))
        return System([x, th], bodies=[cart, bob], V=m * g * bob.position[1], P=-c * th.diff(t) ** 2 / 2,
                      rayleigh=b * x.diff(t) ** 2 / 2,
                      forces=[Force(bob, (u * sp.cos(th), 0)), {x: u}], derivation=d)

    s, e = _check_pair(make, inputs_values={"u": 0.7})
    init = {"x": 0.1, "theta": 0.4, "x_dot": 0.0, "theta_dot": -0.2}
    vals = {k: v for k, v in _values(e.derived).items()}
    drive = {"u": lambda tt: 0.5 * math.sin(3 * tt)}
    a = s.simulate(2.0, init, vals, inputs=drive, rtol=1e-11, atol=1e-12)
    b = e.simulate(2.0, init, vals, inputs=drive, rtol=1e-11, atol=1e-12)
    assert np.allclose(a.y, b.y, rtol=1e-7, atol=1e-8)
    for key in ("energy", "jacobi", "power"):  # the energy report from the compact T agrees with the expanded one
        assert np.allclose(a.diagnostics[key], b.diagnostics[key], rtol=1e-7, atol=1e-8)


def test_holonomic_constraint_and_prescribed_support():
    def make(d):
        x, y = coordinates("x y")
        m, l, g, w, a = parameters("m l g omega a")
        support = coordinates("s")
        return System([x, y], bodies=[Particle(m, (support + x, y))], V=m * g * y, derivation=d,
                      prescribed={support: a * sp.cos(w * t)},
                      constraints=[Holonomic(x**2 + y**2 - l**2, "rod")])

    _check_pair(make)


def test_dry_friction_sign_terms_simulate_like_expanded():
    def make(d):
        x, th = coordinates("x theta")
        m, l, g, mu = parameters("m l g mu")
        bob = Particle(m, (x + l * sp.sin(th), -l * sp.cos(th)))
        return System([x, th], bodies=[Particle(m, (x, 0)), bob], V=m * g * bob.position[1],
                      P=-mu * m * g * sp.Abs(x.diff(t)), derivation=d)

    s, e = make("structural"), make("expanded")
    init = {"x": 0.0, "theta": 0.8, "x_dot": 0.3, "theta_dot": 0.0}
    vals = {"m": 1.0, "l": 1.0, "g": 9.81, "mu": 0.2}
    for friction in ("regularize", "events"):
        a = s.simulate(1.5, init, vals, friction=friction, rtol=1e-10, atol=1e-11)
        b = e.simulate(1.5, init, vals, friction=friction, rtol=1e-10, atol=1e-11)
        assert np.allclose(a.y[-1], b.y[-1], rtol=1e-6, atol=1e-7)
    assert "_expanded" not in s.derived.__dict__


def test_simulate_nlink_agrees_with_expanded():
    init = {**{f"q{i + 1}": 0.4 - 0.1 * i for i in range(6)}, **{f"q{i + 1}_dot": 0.0 for i in range(6)}}
    a = n_link_pendulum(6).simulate(1.0, init, {"g": 9.81}, rtol=1e-11, atol=1e-12)
    b = n_link_pendulum(6, derivation="expanded").simulate(1.0, init, {"g": 9.81}, rtol=1e-11, atol=1e-12)
    assert n_link_pendulum(6).derivation == "structural"
    assert np.allclose(a.y, b.y, atol=1e-8)
    energy = a.diagnostics["energy"]  # conservation: the structural energy report (compact T, V)
    assert np.ptp(energy) < 1e-8 * max(1.0, abs(energy[0]))


def test_compile_and_simulate_never_expand(monkeypatch):
    """The simulate path of a structural system reads the structure only: the expanded derivation raises here."""
    import lagrange.derive.lagrange as expanded_module

    def refuse(system):
        raise AssertionError("the expanded derivation ran")

    monkeypatch.setattr(expanded_module, "lagrange_equations", refuse)
    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "0")  # an on-disk entry would hide an expansion from `refuse`
    s = n_link_pendulum(7)
    init = {**{f"q{i + 1}": 0.3 for i in range(7)}, **{f"q{i + 1}_dot": 0.0 for i in range(7)}}
    for method in ("DOP853", "Radau", "auto"):
        tr = s.simulate(0.5, init, {"g": 9.81}, method=method, n_points=5)
        assert np.isfinite(tr.y).all() and np.isfinite(tr.diagnostics["jacobi"]).all()
    disc = _disc("structural")
    model = disc.compile({"m": 2.0, "g": 9.81, "r": 0.4})
    assert model.m == 2
    eqs = s.derived
    assert eqs.is_conservative and eqs.is_autonomous and [p.name for p in eqs.parameters] == ["g"]
    assert pickle.loads(pickle.dumps(eqs)) == eqs
    with pytest.raises(AssertionError, match="expanded derivation ran"):
        eqs.mass_matrix  # noqa: B018 - the analysis fields are the expanded equations, derived on demand


def test_expansion_is_served_by_the_derivation_cache(monkeypatch, tmp_path):
    """The expanded fields of structural equations (the Taylor tape, heyoka, analyses) go through the on-disk
    derivation cache: a second declaration of the same system loads them instead of deriving again."""
    from lagrange.codegen import derivation_cache as dc

    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "1")
    first = n_link_pendulum(6).derived.mass_matrix
    hits = dc.statistics()["derived"]["hit"]
    again = n_link_pendulum(6)
    assert again.derivation == "structural"
    assert again.derived.mass_matrix == first == n_link_pendulum(6, derivation="expanded").derived.mass_matrix
    assert dc.statistics()["derived"]["hit"] >= hits + 2  # the structural system's expansion, then the expanded one


def test_analysis_fields_are_the_expanded_equations():
    s, e = n_link_pendulum(6), n_link_pendulum(6, derivation="expanded")
    assert s.derivation == "structural" and e.derivation == "expanded"
    assert s.derived.mass_matrix == e.derived.mass_matrix and s.derived.forcing == e.derived.forcing
    assert s.equations() == e.equations()
    assert sp.simplify(s.T - e.T) == 0
    replaced = dataclasses.replace(s.derived, name="renamed")
    assert type(replaced) is lagrange.derive.equations.Equations and replaced.forcing == e.derived.forcing


def test_pickle_hash_and_equality_do_not_expand():
    eqs = n_link_pendulum(6).derived
    again = pickle.loads(pickle.dumps(eqs))
    assert again == eqs and hash(again) == hash(eqs)
    assert "_expanded" not in eqs.__dict__ and "_expanded" not in again.__dict__
    assert eqs != n_link_pendulum(6, symbolic=True).derived


def test_refusals_and_auto_rule():
    x = coordinates("x")
    m, k = parameters("m k")
    with pytest.raises(DeclarationError, match="'auto', 'expanded', 'structural'"):
        System([x], T=m * x.diff(t) ** 2 / 2, derivation="kane")
    with pytest.raises(DeclarationError, match="T is given directly"):
        System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, derivation="structural")
    with pytest.raises(DeclarationError, match="T is given directly"):
        System([x], T=m * x.diff(t) ** 2 / 2, bodies=[Particle(m, (x,))], derivation="structural")
    qs = coordinates("a b c d")
    quat = RigidBody(m, (1, 2, 3), orientation=lagrange.Quaternion(*qs))
    with pytest.raises(DeclarationError, match="Quaternion"):
        System(list(qs), bodies=[quat], derivation="structural")
    assert System(list(qs), bodies=[quat]).derivation == "expanded"  # auto never takes what it cannot do
    with pytest.raises(DeclarationError, match="changes with the coordinates or t"):
        System([x], bodies=[Particle(m * (1 + t), (x,))], derivation="structural")
    a = coordinates("a")
    with pytest.raises(DeclarationError, match="changes with the coordinates or t"):
        System([a], bodies=[RigidBody(m, (1, 1, 1), orientation=rot_z(a), com=(a, 0, 0))], derivation="structural")
    assert n_link_pendulum(5).derivation == "expanded" and n_link_pendulum(6).derivation == "structural"
    assert System([x], bodies=[Particle(m, (x,))], derivation="structural").derivation == "structural"
    with pytest.raises(DeclarationError, match="velocity"):
        System([x], bodies=[Particle(m, (x.diff(t),))], derivation="structural")
    with pytest.raises(DeclarationError, match="not a coordinate|neither a coordinate"):
        y = coordinates("y")
        System([x], bodies=[Particle(m, (x, y))], derivation="structural")
    assert issubclass(DeclarationError, LagrangeError)


@pytest.mark.slow
def test_numba_backend_matches_python():
    pytest.importorskip("numba")
    s = n_link_pendulum(6, symbolic=True)
    vals = _values(s.derived)
    py, nb = s.compile(vals), s.compile(vals, backend="numba")
    y = np.random.default_rng(3).normal(size=12)
    assert np.allclose(np.asarray(py.rhs(0.0, y, py._pcall)), nb.rhs(0.0, y, nb.params), rtol=1e-12, atol=1e-12)
    disc = _disc("structural")
    p = {"m": 2.0, "g": 9.81, "r": 0.4}
    py, nb = disc.compile(p), disc.compile(p, backend="numba")
    y = np.random.default_rng(4).normal(size=10)
    assert np.allclose(np.asarray(py.dynamics(0.0, y, py._pcall)), nb.dynamics(0.0, y, nb.params), atol=1e-10)


@pytest.mark.slow
def test_bicycle_structural_matches_expanded():
    from lagrange_problems import bench_bicycle as bb

    s, e = bb.whipple_bicycle(derivation="structural"), bb.whipple_bicycle(derivation="expanded")
    ms, me = s.compile(bb.PARAMS), e.compile(bb.PARAMS)
    rng = np.random.default_rng(5)
    for _ in range(3):
        y = rng.normal(size=16) * 0.3
        a, b = np.asarray(ms.dynamics(0.0, y, ms._pcall)), np.asarray(me.dynamics(0.0, y, me._pcall))
        assert np.abs(a - b).max() < 1e-9 * np.abs(b).max()


@pytest.mark.parametrize("make", [_disc, lambda d: n_link_pendulum(4, symbolic=True, derivation=d)])
def test_numpy_assembly_matches_straight_line(make, monkeypatch):
    """Both python forms of the generated code (straight-line scalars for small systems, numpy arrays above
    SCALAR_LIMIT) give the same q̈ and λ."""
    import lagrange.codegen.structural_source as ss

    s = make("structural")
    eqs = s.derived
    vals = _values(eqs)
    model = s.compile(vals)
    assert "_gram" not in model.source  # small: straight-line
    monkeypatch.setattr(ss, "SCALAR_LIMIT", 0)
    src = ss.structural_source(eqs, n_params=len(model.params), flavour="python")
    assert "_gram(J, w" in src
    namespace: dict = {}
    exec(compile(src, "<test>", "exec"), namespace)  # noqa: S102 - generated code under test
    y = np.random.default_rng(7).normal(size=2 * eqs.n) * 0.5
    a = np.asarray(namespace["rhs"](0.0, y, model._pcall), dtype=float)
    b = np.asarray(model.dynamics(0.0, y, model._pcall), dtype=float)
    assert np.abs(a - b).max() < 1e-10 * max(1.0, np.abs(b).max())


def test_taylor_reads_the_expanded_equations_without_deriving_the_structural_ones(monkeypatch):
    """method="taylor" (a Taylor-series method: the whole right-hand side as one expression) on a structural
    system takes System.expanded directly: the structural derivation it would not use never runs, and the result
    is the expanded system's."""
    pytest.importorskip("lagrange.integrate.taylor_run")
    import lagrange.derive.structural as structural_module
    from lagrange.integrate.taylor_run import taylor_ready

    init = {**{f"q{i + 1}": 0.2 * (-1) ** i for i in range(6)}, **{f"q{i + 1}_dot": 0.0 for i in range(6)}}
    e = n_link_pendulum(6, derivation="expanded")
    if not taylor_ready(e.derived):
        pytest.skip("no Taylor tape interpreter on this machine")
    b = e.simulate(1.0, init, {"g": 9.81}, method="taylor", rtol=1e-12, atol=1e-12, n_points=3)

    def refuse(system):
        raise AssertionError("the structural derivation ran")

    monkeypatch.setattr(structural_module, "structural_equations", refuse)
    s = n_link_pendulum(6)
    assert s.derivation == "structural"
    a = s.simulate(1.0, init, {"g": 9.81}, method="taylor", rtol=1e-12, atol=1e-12, n_points=3)
    assert np.allclose(a.y, b.y, rtol=0, atol=1e-12)
    assert not s.expanded.is_structural and s.expanded.mass_matrix == e.derived.mass_matrix
    with pytest.raises(AssertionError, match="structural derivation ran"):
        s.derived  # noqa: B018 - every other method still reads the structural equations


def test_the_expanded_equations_are_derived_once_per_system(monkeypatch):
    """With the derivation cache off, repeated Taylor runs of a structural system and its structural equations'
    expanded fields share one expanded derivation (System.expanded), and a pickled System does not carry it."""
    import lagrange.derive.lagrange as expanded_module

    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "0")
    real, calls = expanded_module.lagrange_equations, []

    def counted(system):
        calls.append(system)
        return real(system)

    monkeypatch.setattr(expanded_module, "lagrange_equations", counted)
    s = n_link_pendulum(6)
    first = s.expanded
    assert s.expanded is first and s.derived.expanded() is first and s.derived.mass_matrix == first.mass_matrix
    assert len(calls) == 1
    assert "_expanded_equations" not in pickle.loads(pickle.dumps(s)).__dict__


def test_auto_weighs_the_taylor_method_only_when_the_expanded_equations_are_at_hand(monkeypatch, tmp_path):
    """method="auto" on a structural system (auto × structural × the derivation cache): the Taylor tape needs the
    expanded equations, so auto weighs the Taylor method only when they cost no derivation — derived already on
    this System or stored on disk — and then runs it on them, number for number as method="taylor"; otherwise it
    says why it did not, and never derives them to decide."""
    from lagrange.codegen import derivation_cache as dc
    from lagrange.integrate.taylor import available_interpreter

    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "1")
    init = {**{f"q{i + 1}": 0.2 * (-1) ** i for i in range(6)}, **{f"q{i + 1}_dot": 0.0 for i in range(6)}}
    run = dict(rtol=1e-10, atol=1e-10, n_points=4)
    s = n_link_pendulum(6)
    assert s.derivation == "structural" and dc.stored_equations(s) is None and s.expanded_at_hand() is None
    misses = dc.statistics()["derived"]["miss"]
    first = s.simulate(1.0, init, {"g": 9.81}, method="auto", **run)
    assert "_expanded_equations" not in s.__dict__ and dc.statistics()["derived"]["miss"] == misses  # not derived
    assert first.method.startswith("DOP853") and "Taylor method is not weighed" in first.method
    explicit = n_link_pendulum(6).simulate(1.0, init, {"g": 9.81}, method="DOP853", **run)
    assert np.array_equal(first.y, explicit.y)
    expanded = s.expanded  # derived (and stored): now at hand on this System and on disk for a new one
    again = n_link_pendulum(6)
    assert again.expanded_at_hand() == expanded and s.expanded_at_hand() is expanded
    if available_interpreter() != "c":
        return  # the python backend offers Taylor only with the C tape interpreter (or at rtol <= 1e-11)
    for system in (s, n_link_pendulum(6)):
        chosen = system.simulate(1.0, init, {"g": 9.81}, method="auto", **run)
        direct = n_link_pendulum(6).simulate(1.0, init, {"g": 9.81}, method="taylor", **run)
        assert chosen.method.startswith("taylor") and "auto: smooth" in chosen.method
        assert np.array_equal(chosen.y, direct.y)
    # a given model is of the structural equations: auto keeps to the methods that run it
    model = s.compile({"g": 9.81})
    given = s.simulate(1.0, init, {"g": 9.81}, method="auto", model=model, **run)
    assert not given.method.startswith("taylor") and np.allclose(given.y, direct.y, atol=1e-7)


def test_stored_equations_loads_without_deriving_or_counting_a_miss(monkeypatch, tmp_path):
    from lagrange.codegen import derivation_cache as dc

    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "1")
    x = coordinates("x")
    m, k = parameters("m k")
    s = System([x], bodies=[Particle(m, (x,))], V=k * x**2 / 2)
    before = dc.statistics()["derived"]
    assert dc.stored_equations(s) is None and dc.statistics()["derived"] == before
    derived = s.derived  # a miss: derived and stored
    loaded = dc.stored_equations(System([x], bodies=[Particle(m, (x,))], V=k * x**2 / 2))
    assert loaded == derived and dc.statistics()["derived"]["hit"] == before["hit"] + 1
    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "0")
    assert dc.stored_equations(s) is None
