import pytest
import sympy as sp

from lagrange import DeclarationError, Force, Particle, System, coordinates, delta, parameters, t
from lagrange.simplification import is_zero


def test_coordinates_like_symbols():
    r = coordinates("r")
    a, b = coordinates("a, b")
    assert r.args == (t,) and a.func.__name__ == "a" and b.func.__name__ == "b"
    m, g = parameters("m g")
    assert m.is_positive and g.is_real
    (c,) = (parameters("c", real=True),)
    assert c.is_positive is None


def test_delta_is_variation_with_time_frozen():
    x, y = coordinates("x y")
    b = parameters("b")
    d = delta(b * x**2 * y + sp.sin(t))
    dx, dy = sp.Symbol("delta_x", real=True), sp.Symbol("delta_y", real=True)
    assert sp.expand(d - (2 * b * x * y * dx + b * x**2 * dy)) == 0
    with pytest.raises(ValueError, match="velocities"):
        delta(x.diff(t))


def _problems(exc):
    return "\n".join(exc.value.problems)


def test_validation_collects_every_problem():
    x, y = coordinates("x y")
    m, k = parameters("m k")
    with pytest.raises(DeclarationError) as exc:
        # a plain Symbol('t') is sympy.physics.mechanics' time and is taken as lagrange.t; another 't' is refused
        System([x], T=m * x.diff(t) ** 2 / 2, V=k * y + sp.Symbol("x") + sp.Symbol("t", positive=True) + x.diff(t))
    text = _problems(exc)
    assert len(exc.value.problems) == 4
    assert "y(t), which is not a coordinate" in text
    assert "velocity" in text and "V must depend" in text
    assert "lagrange.t" in text
    assert "clashes with coordinate names" in text


def test_acceleration_and_strict_parameters_rejected():
    x = coordinates("x")
    m, k = parameters("m k")
    c = sp.Symbol("c")
    with pytest.raises(DeclarationError, match="accelerations"):
        System([x], T=m * x.diff(t) ** 2 / 2, P=x.diff(t, 2))
    with pytest.raises(DeclarationError, match="neither a coordinate, a declared parameter"):
        System([x], T=m * x.diff(t) ** 2 / 2, V=c * x**2, parameters=[m, k])


def test_force_on_unknown_coordinate_and_bad_coordinate():
    x, y = coordinates("x y")
    m = parameters("m")
    with pytest.raises(DeclarationError, match="not a coordinate of this system"):
        System([x], T=m * x.diff(t) ** 2 / 2, forces={y: 1})
    with pytest.raises(DeclarationError, match="is not a coordinate"):
        System([sp.Symbol("x")], T=0)
    with pytest.raises(DeclarationError, match="no kinetic energy"):
        System([x])
    with pytest.raises(DeclarationError, match="more than once"):
        System([x, x], T=m * x.diff(t) ** 2)


def test_system_is_immutable():
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2)
    with pytest.raises(AttributeError):
        s.V = 1


def test_three_ways_to_give_generalized_forces_agree():
    """Wells 4.10 (Cartesian force at a point), 4.12 (virtual work) and a direct F_q give the same F_q."""
    x, th = coordinates("x theta")
    m, l, F = parameters("m l F")
    pos = (x + l * sp.sin(th), -l * sp.cos(th))
    p = Particle(m, pos)
    s1 = System([x, th], bodies=[p], forces=[Force(p, (F, 0))])
    s2 = System([x, th], bodies=[p], forces=F * delta(x + l * sp.sin(th)))
    s3 = System([x, th], bodies=[p], forces={x: F, th: F * l * sp.cos(th)})
    for s in (s1, s2):
        for q in (x, th):
            assert is_zero(s.forces[q] - s3.forces[q])


def test_virtual_work_must_be_linear_in_displacements():
    x = coordinates("x")
    with pytest.raises(DeclarationError, match="without a virtual displacement"):
        System([x], T=x.diff(t) ** 2, forces=delta(x) + 3)


def test_prescribed_motion_is_substituted():
    """Wells Ex. 4.9 style: a support with prescribed motion s(t) is not a degree of freedom."""
    x, s = coordinates("x s")
    m, k, A, w = parameters("m k A omega")
    sys_ = System([x], bodies=[Particle(m, (x,))], V=k * (x - s) ** 2 / 2, prescribed={s: A * sp.sin(w * t)})
    (eq,) = sys_.equations()
    assert is_zero(eq.lhs - eq.rhs - (m * x.diff(t, 2) + k * (x - A * sp.sin(w * t))))
    with pytest.raises(DeclarationError, match="both a coordinate and prescribed"):
        System([x, s], T=x.diff(t) ** 2, prescribed={s: t})
