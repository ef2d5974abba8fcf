"""The symengine round trip (lagrange.symengine_bridge): the node-by-node Restorer gives the same sympy expression
as sympy's own conversion followed by xreplace of the symbols, with the original symbols' assumptions."""

import pytest
import sympy as sp

from lagrange.symengine_bridge import Restorer, carries

se = pytest.importorskip("symengine")


def _reference(expr, symbols):
    back = {sp.Symbol(s.name): s for s in symbols if sp.Symbol(s.name) != s}
    return sp.sympify(expr).xreplace(back)


def test_restorer_matches_sympify_then_xreplace():
    a, b = sp.symbols("a b", positive=True)
    x, y = sp.symbols("x y", real=True)
    z = sp.Symbol("z")
    e = (a * sp.sin(x) ** 2 * sp.cos(y) + sp.Rational(3, 7) * b / (x + y) ** 3 + sp.pi * sp.exp(-z)
         + sp.atan(a * x) - sp.sqrt(b) * sp.tanh(y) + sp.E * sp.log(a + z))
    es = se.sympify(e).diff(se.Symbol("x")) + se.sympify(e) * se.Symbol("y")
    restore = Restorer({a, b, x, y, z})
    got = restore(es)
    want = _reference(es, {a, b, x, y, z})
    assert got == want  # the same canonical sympy expression, not only the same value
    assert {s for s in got.free_symbols if s.name == "a"} == {a}  # the positive symbol, not a plain one
    point = {a: 0.7, b: 1.3, x: 0.2, y: -0.4, z: 0.9}
    assert float(got.subs(point)) == pytest.approx(float(want.subs(point)), rel=1e-14)


def test_restorer_leaves_plain_results_and_sympy_input_alone():
    x = sp.Symbol("x")
    assert Restorer({x})(se.Integer(3)) == 3
    assert Restorer({x})(x + 1) == x + 1  # a sympy expression passes through


def test_carries_visits_shared_subexpressions_and_still_refuses():
    x = sp.Symbol("x")
    shared = sp.sin(x) * sp.cos(x)
    assert carries([sp.Add(*[shared * k for k in range(1, 50)])])
    assert not carries([shared + sp.Float(0.5)])  # a float is never carried
    assert not carries([shared + sp.Abs(x)])
    assert not carries([x + sp.Symbol("x", positive=True)])  # two symbols of one name
