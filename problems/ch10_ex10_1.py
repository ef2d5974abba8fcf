"""Wells, Example 10.1 — double pendulum with gravity and viscous drag: exact equations (10.1) and their
linearization (10.2) about the hanging equilibrium."""

import sympy as sp

from lagrange import Particle, System, characteristic_roots, coordinates, linearize, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

th, ph = coordinates("theta phi")
m1, m2, r1, r2, g, b1, b2 = parameters("m1 m2 r1 r2 g b1 b2")

X1, Y1 = r1 * sp.sin(th), -r1 * sp.cos(th)
X2, Y2 = X1 + r2 * sp.sin(ph), Y1 - r2 * sp.cos(ph)
# v² simplified with trigsimp (sin² + cos² = 1) so that the per-equation ratio test (sp.cancel) sees it
v1sq = sp.trigsimp(sp.expand(X1.diff(t) ** 2 + Y1.diff(t) ** 2))
v2sq = sp.trigsimp(sp.expand(X2.diff(t) ** 2 + Y2.diff(t) ** 2))

# θ, φ: absolute angles of r1, r2 from the downward vertical; drag b_i v_i on each bob through Wells' P < 0.
system = System(
    [th, ph],
    bodies=[Particle(m1, (X1, Y1), name="m1"), Particle(m2, (X2, Y2), name="m2")],
    V=m1 * g * Y1 + m2 * g * Y2,
    P=-sp.Rational(1, 2) * (b1 * v1sq + b2 * v2sq),
    name="double pendulum with viscous drag",
)

thd, phd, thdd, phdd = th.diff(t), ph.diff(t), th.diff(t, 2), ph.diff(t, 2)


def _linear_residuals(s):
    """a s'' + b s' + c s from the library's linearization about θ = φ = 0."""
    lin = linearize(s, about={th: 0, ph: 0})
    q = sp.Matrix(s.coordinates)
    return list(lin.a * q.diff(t, 2) + lin.b * q.diff(t) + lin.c * q)


def _stable(s):
    roots = characteristic_roots(linearize(s), {m1: 1.0, m2: 0.5, r1: 1.0, r2: 0.8, g: 9.8, b1: 0.3, b2: 0.2})
    return sp.Integer(int(all(roots.real < 0)))


PROBLEM = Problem(
    id="ex10.1",
    title="Double pendulum with viscous drag: exact equations (10.1) and linearized equations (10.2)",
    chapter=10,
    source="Wells, Example 10.1 (Fig. 10-1(a)), eqs. (10.1), (10.2); Sec. 10.17 for stability",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (m1 + m2) * r1**2 * thd**2 + m2 * r1 * r2 * thd * phd * sp.cos(ph - th)
                      + sp.Rational(1, 2) * m2 * r2**2 * phd**2),
        PotentialEnergy(-(m1 + m2) * g * r1 * sp.cos(th) - m2 * g * r2 * sp.cos(ph)),
        EquationsOfMotion(
            [
                sp.Eq((m1 + m2) * r1**2 * thdd + m2 * r1 * r2 * phdd * sp.cos(ph - th)
                      - m2 * r1 * r2 * phd**2 * sp.sin(ph - th) + (m1 + m2) * g * r1 * sp.sin(th)
                      + (b1 + b2) * r1**2 * thd + b2 * r1 * r2 * phd * sp.cos(ph - th), 0),
                sp.Eq(m2 * r2**2 * phdd + m2 * r1 * r2 * thdd * sp.cos(ph - th)
                      + m2 * r1 * r2 * thd**2 * sp.sin(ph - th) + m2 * g * r2 * sp.sin(ph)
                      + b2 * r2**2 * phd + b2 * r1 * r2 * thd * sp.cos(ph - th), 0),
            ],
            per_equation=True,
        ),
        Quantity(
            "linearized equations (10.2): a s'' + b s' + c s",
            _linear_residuals,
            [
                (m1 + m2) * r1**2 * thdd + (b1 + b2) * r1**2 * thd + (m1 + m2) * g * r1 * th
                + m2 * r1 * r2 * phdd + b2 * r1 * r2 * phd,
                m2 * r1 * r2 * thdd + b2 * r1 * r2 * thd + m2 * r2**2 * phdd + b2 * r2**2 * phd + m2 * g * r2 * ph,
            ],
            description="linearized equations (10.2)",
        ),
        Quantity("stable (all Re λ < 0) for small drag", _stable, sp.Integer(1),
                 description="Sec. 10.16-10.17: V positive definite, P < 0 -> every root has negative real part"),
    ],
    simulation=Simulation(
        params={m1: 1.0, m2: 0.5, r1: 1.0, r2: 0.8, g: 9.8, b1: 0.3, b2: 0.2},
        initial={th: 0.4, ph: -0.3, thd: 0.0, phd: 0.5},
        t_end=10.0,
    ),
    correction="The stability statement is the book's general result of Sec. 10.16-10.17 (V positive definite, "
               "small viscous drag: complex roots with negative real parts), checked here at sample numbers; the "
               "book gives no numeric roots for this example.",
)
