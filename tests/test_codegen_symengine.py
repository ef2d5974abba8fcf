"""Code generation printed straight from symengine (``fuse(..., printable=True)``) against the sympy route and the
uncompiled reference, and the symbol carriers of :func:`lagrange.symengine_bridge.to_symengine`."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange.examples import n_link_pendulum

se = pytest.importorskip("symengine")


def _sources(system, monkeypatch, params):
    """(symengine-printed model, sympy-printed model, reference model) of ``system``."""
    from lagrange.codegen import cse as cse_module

    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "0")
    fast = system.compile(params, backend="python")
    with monkeypatch.context() as m:
        m.setattr(cse_module, "_symengine_fuse", lambda eqs, crhs: None)
        slow = system.compile(params, backend="python")
    return fast, slow, system.compile(params, backend="reference")


def test_symengine_printed_source_matches_sympy_route_and_reference(monkeypatch):
    """A 6-link pendulum with symbolic masses and lengths (above the CSE size limit, so symengine prints it):
    the printed source differs from sympy's, the values agree with it and with the reference."""
    s = n_link_pendulum(6, symbolic=True, derivation="expanded")  # the expanded route's CSE and printing
    params = {"g": 9.81, **{f"m{i}": 1.0 + 0.1 * i for i in range(1, 7)},
              **{f"l{i}": 0.5 + 0.2 * i for i in range(1, 7)}}
    fast, slow, ref = _sources(s, monkeypatch, params)
    assert fast.source != slow.source and "math.sin(" in fast.source
    rng = np.random.default_rng(6)
    for _ in range(20):
        y = rng.uniform(-2, 2, 12)
        b = np.asarray(ref.fun(0.3, y))
        scale = np.max(np.abs(b))
        assert np.allclose(fast.fun(0.3, y), slow.fun(0.3, y), rtol=1e-12, atol=1e-12 * scale)
        assert np.allclose(fast.fun(0.3, y), b, rtol=1e-11, atol=1e-11 * scale)


def test_symengine_printing_with_constraints_and_explicit_time(monkeypatch):
    """Particles on a rotating chain: a holonomic constraint, explicit t and pi/E constants — the
    symengine-printed source agrees with the sympy route and the reference, multipliers included. (Input
    symbols are not carried by symengine: with an input the sympy route prints, as
    tests/test_inputs.py covers.)"""
    q = lg.coordinates("x y a b")
    x, y, a, b = q
    m, k, w, g = lg.parameters("m k w g")
    t = lg.t
    X = [x + sp.cos(w * t) * sp.sin(a), y + sp.sin(a) * sp.cos(b) + sp.pi / 7]
    bodies = [lg.Particle(m, (x, y)), lg.Particle(m * sp.E / 3, tuple(X)),
              lg.Particle(m / 2, (X[0] + sp.sin(b), X[1] - sp.cos(b)))]
    V = k * (x**2 + y**2) / 2 + m * g * y
    system = lg.System(list(q), bodies=bodies, V=V, constraints=[x**2 + y**2 - 4])
    params = {"m": 1.3, "k": 2.0, "w": 0.7, "g": 9.81}
    from lagrange.codegen import cse as cse_module

    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "0")
    assert cse_module._symengine_fuse(system.derived, None) is not None, "expected the symengine route"
    fast = system.compile(params, backend="python")
    with monkeypatch.context() as mp:
        mp.setattr(cse_module, "_symengine_fuse", lambda eqs, crhs: None)
        slow = system.compile(params, backend="python")
    ref = system.compile(params, backend="reference")
    assert fast.source != slow.source
    rng = np.random.default_rng(4)
    for _ in range(10):
        yy = rng.uniform(-1, 1, 8)
        yy[:2] = 2 * yy[:2] / np.hypot(*yy[:2])
        r = np.asarray(ref.fun(0.9, yy))
        scale = np.max(np.abs(r))
        assert np.allclose(fast.fun(0.9, yy), slow.fun(0.9, yy), rtol=1e-11, atol=1e-11 * scale)
        assert np.allclose(fast.fun(0.9, yy), r, rtol=1e-9, atol=1e-9 * scale)


def test_carriers_keep_assumptions_across_calls():
    """Same-named symbols with different assumptions in successive conversions come back as themselves
    (symengine compares symbols by name; sympy's cache once returned the earlier one)."""
    from lagrange.symengine_bridge import to_symengine

    r_pos, r_real = sp.Symbol("r", positive=True), sp.Symbol("r", real=True)
    m = sp.Symbol("m", positive=True)
    for r in (r_pos, r_real, r_pos):
        (e,) = to_symengine([m * r**2 * sp.sin(r) / 2], {r, m})
        back = sp.sympify(e.diff(to_symengine([r], {r, m})[0]))
        assert back.free_symbols == {r, m}
        assert sp.expand(back - sp.diff(m * r**2 * sp.sin(r) / 2, r)) == 0
    with pytest.raises(ValueError, match="share a name"):
        to_symengine([r_pos + r_real], {r_pos, r_real})


def test_symengine_printing_keeps_domain_errors():
    """``x**(-1/2)`` and ``sqrt(x)`` print as ``math.sqrt`` (a domain error for x < 0, as the sympy printer
    gives), never as a power that Python would turn into a complex number."""
    from lagrange.codegen.source import print_expr

    y0, p0 = se.symbols("y0 p0")
    for e in (y0 ** se.Rational(-1, 2) + p0, se.sqrt(y0) * p0, 1 / se.sqrt(y0 + p0)):
        text = print_expr(e)
        assert "math.sqrt(" in text, text
        with pytest.raises(ValueError):
            eval(text, {"math": __import__("math"), "y0": -2.0, "p0": 0.5})  # noqa: S307 - our own printed text
    text = print_expr(se.pi * y0 + se.E + se.exp(y0) + se.Rational(1, 3))
    assert sorted(text.split(" + ")) == ["1/3", "math.e", "math.exp(y0)", "math.pi*y0"]
