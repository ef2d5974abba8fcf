from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from lagrange import ParameterError, Particle, SingularMassMatrixError, System, coordinates, parameters, t
from lagrange.codegen.numeric import compile_equations
from lagrange.examples import n_link_pendulum


@pytest.mark.parametrize("n", [1, 2, 4])
@pytest.mark.parametrize("backend", ["python", "numba"])
def test_backends_agree_with_reference(n, backend):
    s = n_link_pendulum(n)
    ref = s.compile({"g": 9.81}, backend="reference")
    fast = s.compile({"g": 9.81}, backend=backend)
    rng = np.random.default_rng(n)
    for _ in range(20):
        y = rng.uniform(-2, 2, 2 * n)
        a, b = np.asarray(fast.fun(0.3, y)), ref.fun(0.3, y)
        assert np.allclose(a, b, rtol=1e-12, atol=1e-12 * np.max(np.abs(b)))


def test_dense_mass_matrix_with_time_and_parameters():
    """A non-diagonal, time-dependent M exercises every branch of the unrolled LDL^T."""
    x, y, z = coordinates("x y z")
    m1, m2, k, w = parameters("m1 m2 k omega")
    bodies = [
        Particle(m1, (x + y * sp.cos(w * t), y * sp.sin(w * t) + z)),
        Particle(m2, (x - z, y + z * x, x * y)),
    ]
    s = System([x, y, z], bodies=bodies, V=k * (x**2 + y**2 + z**2) / 2)
    params = {"m1": 1.3, "m2": 0.7, "k": 2.0, "omega": 1.1}
    ref = s.compile(params, backend="reference")
    for backend in ("python", "numba"):
        fast = s.compile(params, backend=backend)
        rng = np.random.default_rng(7)
        for _ in range(10):
            yv = rng.uniform(-1, 1, 6)
            assert np.allclose(np.asarray(fast.fun(0.7, yv)), ref.fun(0.7, yv), rtol=1e-11, atol=1e-12)


def test_missing_and_unknown_parameters_listed():
    s = n_link_pendulum(2, symbolic=True)
    with pytest.raises(ParameterError) as exc:
        s.compile({"g": 1.0, "m1": 1.0, "zz": 2})
    msg = str(exc.value)
    assert "l1" in msg and "l2" in msg and "m2" in msg and "zz" in msg
    with pytest.raises(ParameterError, match="not finite"):
        n_link_pendulum(1).compile({"g": float("nan")})


def test_singular_mass_matrix_names_coordinates():
    """Wells Prob. 3.7: a massless point gives M = [[m, m r cos θ], [m r cos θ, m r²]], singular at
    θ = 0; the error names the coordinates."""
    xp, th = coordinates("x_p theta")
    m, r, k, g = parameters("m r k g")
    bob = Particle(m, (xp + r * sp.sin(th), -r * sp.cos(th)))
    s = System([xp, th], bodies=[bob], V=k * xp**2 - m * g * r * sp.cos(th))
    model = s.compile({"m": 1, "r": 1, "k": 1, "g": 9.81})
    with pytest.raises(SingularMassMatrixError) as exc:
        model.fun(0.0, np.array([0.1, 0.0, 0.0, 0.0]))
    assert "x_p" in str(exc.value) and "theta" in str(exc.value)
    with pytest.raises(SingularMassMatrixError):
        s.simulate(1.0, {xp: 0.1, th: 0.0, xp.diff(t): 0, th.diff(t): 0}, {"m": 1, "r": 1, "k": 1, "g": 9.81})


def test_unknown_backend():
    from lagrange import BackendError

    with pytest.raises(BackendError, match="unknown backend"):
        compile_equations(n_link_pendulum(1).derived, {"g": 1}, backend="fortran")


def test_generated_source_is_straight_line_and_uses_cse():
    model = n_link_pendulum(3).compile({"g": 9.81})
    src = model.source
    assert "c0 =" in src and "def rhs(t, y, p):" in src
    assert "for " not in src and "solve" not in src  # unrolled LDL^T, no loops or library calls


def test_numba_cache_reused_and_corruption_recovered(tmp_path, monkeypatch):
    """Numba's cache of the generated module is sealed in one bundle keyed by a hash of its source; a
    corrupted bundle is rebuilt."""
    from lagrange.codegen import numba_backend as nb
    from lagrange.codegen.cache import cache_dir, read_verified
    from lagrange.errors import CacheIntegrityWarning

    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    # a system no other test compiles: a module already staged in this process (another test of the same
    # xdist worker) is not compiled again, so numba would write nothing to this test's cache
    from lagrange import System, coordinates, parameters, t

    q1, q2 = coordinates("q1 q2")
    kc = parameters("k_numba_cache_test")
    s = System([q1, q2], T=(q1.diff(t) ** 2 + 2 * q2.diff(t) ** 2) / 2,
               V=kc * (q1**2 + q2**2) / 2 + q1**2 * q2**2 / 7)
    y = np.array([0.3, -0.2, 0.1, 0.4])
    model = s.compile({"k_numba_cache_test": 9.81}, backend="numba")
    first = model.fun(0.0, y)
    bundles = list(cache_dir().glob("rhs_*.numba"))
    assert len(bundles) == 1 and read_verified(bundles[0]), "numba wrote no cache"
    bundles[0].write_bytes(b"garbage")
    staged = Path(model.dynamics.py_func.__code__.co_filename)
    nb.purge_numba_cache(model.dynamics.py_func.__module__, staged)  # as a fresh process would be
    nb._STAGED.pop(staged)
    with pytest.warns(CacheIntegrityWarning):
        monkeypatch.setattr("lagrange.codegen.cache._warned", False)
        again = s.compile({"k_numba_cache_test": 9.81}, backend="numba").fun(0.0, y)
    assert np.array_equal(first, again)
    assert len(list(cache_dir().glob("rhs_*.numba"))) == 1 and read_verified(bundles[0])


def test_cse_variants_agree_with_reference(monkeypatch):
    """The three CSE routes — sympy with factor_terms (small sets), symengine's CSE and sympy without
    factor_terms (large sets, with and without symengine) — give different sources for the same function,
    checked against the uncompiled reference; temporaries keep their real assumption."""
    from lagrange.codegen import cse as cse_module

    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "0")  # generate afresh, not from the source cache
    s = n_link_pendulum(3)
    sources = {}
    variants = [("small", 10**9, True), ("sympy", 0, False)]
    if cse_module.symengine() is not None:
        variants.append(("symengine", 0, True))
    ref = s.compile({"g": 9.81}, backend="reference")
    rng = np.random.default_rng(3)
    states = [rng.uniform(-2, 2, 6) for _ in range(20)]
    for name, limit, with_symengine in variants:
        with monkeypatch.context() as m:
            m.setattr(cse_module, "FACTOR_TERMS_LIMIT", limit)
            if not with_symengine:
                m.setattr(cse_module, "_symengine_cse", lambda exprs: None)
                m.setattr(cse_module, "_symengine_fuse", lambda eqs, crhs: None)
            cse_module._FUSED.clear()  # fuse remembers its result per equations: run this variant's CSE
            fused, _ = cse_module.fuse(s.derived)
            assert all(c.is_real for c, _ in fused.temporaries)
            model = s.compile({"g": 9.81}, backend="python")
        sources[name] = model.source
        for y in states:
            b = ref.fun(0.1, y)
            assert np.allclose(np.asarray(model.fun(0.1, y)), b, rtol=1e-12, atol=1e-12 * np.max(np.abs(b))), name
    assert len(set(sources.values())) == len(sources)


def test_symengine_cse_refuses_what_it_cannot_carry_back():
    import pytest

    pytest.importorskip("symengine")
    from lagrange.codegen.cse import _symengine_cse

    y0, x0 = sp.symbols("y0 x0", real=True)
    assert _symengine_cse([sp.sign(y0) * sp.sin(y0), sp.sin(y0) ** 2]) is None  # sign: not carried
    assert _symengine_cse([sp.Float("0.1", 30) * sp.sin(y0)]) is None  # a float's precision
    assert _symengine_cse([x0 * sp.sin(y0), sp.sin(y0) ** 2]) is None  # clashes with symengine's names
    repl, red = _symengine_cse([sp.sin(y0) * 2, sp.sin(y0) ** 2])
    assert repl == [(sp.Symbol("c0", real=True), sp.sin(y0))] and red[1] == sp.Symbol("c0", real=True) ** 2


def test_to_symbols_replaces_derivatives_before_functions():
    """q''(t) → q_ddot and q'(t) → q_dot as whole subtrees, then q(t) → q; the inverse restores them."""
    from lagrange.model.coordinates import (
        acceleration_symbol,
        position_symbol,
        to_functions,
        to_symbols,
        velocity_symbol,
    )

    x, y = coordinates("x y")
    e = x.diff(t, 2) * sp.cos(y) + x.diff(t) ** 2 * y.diff(t) + sp.sin(x * t)
    out = to_symbols(e, [x, y])
    X, Y = position_symbol(x), position_symbol(y)
    assert out == (acceleration_symbol(x) * sp.cos(Y) + velocity_symbol(x) ** 2 * velocity_symbol(y)
                   + sp.sin(X * t))
    assert not out.has(sp.Derivative) and not out.has(x) and to_functions(out, [x, y]) == e


@pytest.mark.parametrize("case", ["top", "time_varying_mass_with_input", "constrained"])
def test_python_mass_matrix_comes_from_the_generated_module(case, monkeypatch):
    """The python backend's ``mass_matrix`` (the initial gimbal-lock check, analyses) is the generated module's own
    ``mass(t, y, p)`` — the same CSE as ``rhs``, no lambdify — and equals M of the derived equations evaluated
    independently (the reference backend: plain lambdify), for a top with Euler angles and a system whose M
    depends on t, with an input among the parameters. With constraints the module's matrix is the augmented
    M + AᵀA, so there is no ``mass`` and M is lambdified as before."""
    import lagrange as lg

    rng = np.random.default_rng(3)
    inputs = None
    if case == "top":
        psi, th, ph = coordinates("psi theta phi")
        M, g, l, I1, I3 = parameters("M g l I1 I3")
        body = lg.RigidBody(M, (I1, I1, I3), orientation=lg.EulerAngles(psi, th, ph), com=(0, 0, l))
        s = System([psi, th, ph], bodies=[body], V=M * g * body.centre_of_mass[2])
        params = {"M": 1.0, "g": 9.81, "l": 0.2, "I1": 0.05, "I3": 0.02}
    else:
        x, y, z = coordinates("x y z")
        m, w, k = parameters("m w k")
        u = lg.inputs("u")
        body = Particle(m * (2 + sp.cos(w * t)), (x, y, x * z))
        track = [lg.Holonomic(x + y - sp.sin(w * t), "track")] if case == "constrained" else []
        s = System([x, y, z], bodies=[body], V=k * (x**2 + y**2 + z**2) / 2, forces={y: u}, constraints=track)
        params, inputs = {"m": 1.3, "w": 0.7, "k": 2.0}, {"u": 0.4}
    model = s.compile(params, inputs=inputs)
    reference = s.compile(params, backend="reference", inputs=inputs)
    generated = case != "constrained"
    assert ("\ndef mass(t, y, p):" in model.source) is generated
    states = [(float(rng.uniform(0, 3)), rng.uniform(-1, 1, 2 * s.derived.n)) for _ in range(5)]
    want = [reference.mass_matrix(tt, state) for tt, state in states]
    if generated:
        monkeypatch.setattr(sp, "lambdify", lambda *a, **k: (_ for _ in ()).throw(AssertionError("lambdified")))
    for (tt, state), expected in zip(states, want):
        got = model.mass_matrix(tt, state)
        assert got.shape == (s.derived.n, s.derived.n) and np.array_equal(got, got.T)
        assert np.allclose(got, expected, rtol=1e-13, atol=1e-13)
