"""The light method table the CLI uses agrees with the methods simulate() dispatches on."""

from lagrange.integrate.fixed import GEOMETRIC
from lagrange.integrate.methods import ADAPTIVE, FIXED_STEP, SCIPY, canonical_method
from lagrange.integrate.scipy_ivp import SCIPY_METHODS


def test_tables_match_the_integrators():
    assert SCIPY == tuple(SCIPY_METHODS)
    assert set(FIXED_STEP) == set(GEOMETRIC)
    assert set(ADAPTIVE) == set(SCIPY_METHODS) | {"taylor", "heyoka", "auto"}


def test_canonical_method_is_case_insensitive():
    assert canonical_method("dop853") == "DOP853"
    assert canonical_method("Taylor") == "taylor"
    assert canonical_method("HEYOKA") == "heyoka"
    assert canonical_method(" RADAU ") == "Radau"
    assert canonical_method("GL4") == "gl4"
    assert canonical_method("rk4") is None
    assert canonical_method(3) is None
