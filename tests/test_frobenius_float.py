"""The double-precision Frobenius screen (lagrange.model.constraints._frobenius_float) never calls an integrable
Pfaffian form non-integrable, and its non-integrable verdicts agree with the exact symbolic test."""

import itertools

import pytest
import sympy as sp

from lagrange.model import constraints as C
from lagrange.simplification import is_zero

pytest.importorskip("symengine")

x, y, z, w = sp.symbols("x y z w", real=True)
r = sp.Symbol("r", positive=True)
t = sp.Symbol("t", real=True)


def _symbolic(a, syms):
    """ω ∧ dω = 0 proved term by term (the exact test, independent of the numeric screens)."""
    for i, j, k in itertools.combinations(range(len(syms)), 3):
        e = (a[i] * (sp.diff(a[k], syms[j]) - sp.diff(a[j], syms[k]))
             + a[j] * (sp.diff(a[i], syms[k]) - sp.diff(a[k], syms[i]))
             + a[k] * (sp.diff(a[j], syms[i]) - sp.diff(a[i], syms[j])))
        if not is_zero(e):
            return False
    return True


FORMS = [
    # rolling disc: dx − r cos(z) dw, dy − r sin(z) dw (not integrable)
    [1, 0, 0, -r * sp.cos(z)],
    [0, 1, 0, -r * sp.sin(z)],
    # exact and integrable-after-a-factor forms, with cancellations only exact arithmetic sees
    [y, x, 0, 0],  # d(xy)
    [sp.exp(x) * sp.sin(y) * z, sp.exp(x) * sp.cos(y) * z, sp.exp(x) * sp.sin(y), 0],  # d(e^x sin y z)
    [2 * x * (x**2 + y**2 + z**2), 2 * y * (x**2 + y**2 + z**2), 2 * z * (x**2 + y**2 + z**2), 0],  # f(r²) d(r²)
    [sp.cos(z) ** 2 + sp.sin(z) ** 2, -1, 0, 0],  # dx − dy written with sin² + cos² (the 40-digit screen
    # called it non-integrable before its derivative scale had a floor)
    [sp.sin(2 * z) - 2 * sp.sin(z) * sp.cos(z) + 1, -1, 0, 0],  # a zero derivative symengine does not see
    # the contact form dz − y dx (not integrable), and a sum of one
    [-y, 0, 1, 0],
    [-y + x, 1, 1, w],
]


@pytest.mark.parametrize("a", FORMS)
def test_float_screen_agrees_with_the_exact_test(a):
    syms = [x, y, z, w]
    a = [sp.sympify(c) for c in a] + [sp.S.Zero]  # no dt term
    exact = _symbolic(a[:4], syms)
    involved = [i for i, s in enumerate(syms + [t]) if a[i] != 0 or any(ai.has(s) for ai in a)]
    verdict = C._frobenius_float(a, syms + [t], involved)
    if exact:
        assert verdict is None  # never "non-integrable" for an integrable form
    else:
        assert verdict is False
    assert C._frobenius(a, syms + [t]) is exact  # the whole test, float screen first
