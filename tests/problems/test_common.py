"""The corpus helper layer (problems/_common.py) and the quadrature used for book answers written as integrals."""

import mpmath
import pytest
import sympy as sp
from lagrange_problems import _common

from lagrange import coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem
from lagrange.corpus.compare import Mismatch, _value, agree
from lagrange.model.coordinates import to_symbols


def test_dry_friction_closed_form_equals_quadrature_of_the_speed():
    x, y, th = coordinates("x y theta")
    f = parameters("f")
    P = _common.dry_friction_along_rod(f, x, y, th, -0.4, 0.7)
    vals = {"x": 0.3, "y": -0.2, "theta": 0.9, "x_dot": 0.8, "y_dot": -0.5, "theta_dot": -1.3, "f": 2.0}
    expr = to_symbols(P, [x, y, th])
    got = float(expr.subs({s: vals[s.name] for s in expr.free_symbols}))
    xd, yd, thd, a = vals["x_dot"], vals["y_dot"], vals["theta_dot"], vals["theta"]
    speed = lambda r: mpmath.sqrt((xd - r * thd * mpmath.sin(a)) ** 2 + (yd + r * thd * mpmath.cos(a)) ** 2)  # noqa: E731
    assert got == pytest.approx(-2.0 * float(mpmath.quad(speed, [-0.4, 0, 0.7])), rel=1e-12)


def test_rod_from_end_is_a_uniform_rod():
    x, y, th = coordinates("x y theta")
    M, l = parameters("M l")
    rod, T_rot = _common.rod_from_end(M, l, x, y, th)
    T = rod.kinetic_energy() + T_rot
    # uniform rod turning about its fixed end: T = ½ (M l²/3) θ̇²
    assert sp.simplify(T.subs({x: 0, y: 0}).doit() - M * l**2 * th.diff(t) ** 2 / 6) == 0


def test_variant_changes_only_what_it_is_given():
    x = coordinates("x")
    m = parameters("m")
    base = Problem(id="ex0.1", title="base", chapter=1, source="Wells, Example 0.1", system=None,
                   answers=[KineticEnergy(m * x.diff(t) ** 2 / 2)], correction="base note", units="cgs")
    v = _common.variant(base, id="p0.2", title="variant", source="Wells, Problem 0.2", chapter=2)
    assert (v.id, v.title, v.source, v.chapter) == ("p0.2", "variant", "Wells, Problem 0.2", 2)
    assert v.answers is base.answers and v.correction == "base note" and v.units == "cgs"
    with pytest.raises(TypeError, match="unknown Problem field.*answer\\b"):
        _common.variant(base, id="p0.3", title="x", source="y", answer=[])


def test_integral_answers_are_evaluated_by_quadrature():
    a, c, u = sp.symbols("a c u", positive=True)
    book = sp.Integral(sp.sin(c * u) * u, (u, 0, a))
    closed = sp.sin(a * c) / c**2 - a * sp.cos(a * c) / c
    pt = {a: sp.Float("1.3", 30), c: sp.Float("0.7", 30)}
    assert abs(_value(book, pt) - _value(closed, pt)) < 1e-25
    agree(closed, book, [a, c], what="integral")
    with pytest.raises(Mismatch):
        agree(closed * (1 + sp.Rational(1, 10**6)), book, [a, c], what="integral")
