"""Wells, Problem 3.15 — mass on a spring whose top block is forced, s = A sin ωt; q from static equilibrium."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Quantity, Simulation

q, s = coordinates("q s")
m, k, A, w, C1, d0 = parameters("m k A omega C_1 delta_0")

# q and s both downward from their rest positions; at static equilibrium gravity balances the static stretch,
# leaving the spring force −k(q − s) on m. The block's motion is prescribed (not a degree of freedom).
system = System(
    [q],
    bodies=[Particle(m, (q,), name="mass")],
    forces=-k * (q - s) * delta(q),
    prescribed={s: A * sp.sin(w * t)},
    name="mass on a spring with a forced support",
)

book_q = C1 * sp.sin(sp.sqrt(k / m) * t + d0) + A * k / (m * (k / m - w**2)) * sp.sin(w * t)


def residual_of_book_solution(sys_):
    eq = sys_.equations()[0]
    res = (eq.lhs - eq.rhs).subs(q, book_q).doit()
    return sp.simplify(res)


PROBLEM = Problem(
    id="p3.15",
    title="Spring-mass with a sinusoidally driven support: effective force k A sin(wt) and the general solution",
    chapter=3,
    source="Wells, Problem 3.15",
    system=system,
    answers=[
        GeneralizedForces({q: -k * q + k * A * sp.sin(w * t)}),
        EquationsOfMotion([sp.Eq(m * q.diff(t, 2) + k * q, k * A * sp.sin(w * t))], per_equation=True),
        Quantity("residual of the book's solution q(t) in the derived equation", residual_of_book_solution, 0),
    ],
    simulation=Simulation(params={m: 1, k: 4, A: 0.1, w: 3}, initial={q: 0, q.diff(t): 0}, t_end=10),
    correction="The equation m q'' + k q = k A sin(wt) is the book's 'effective force k A sin wt' statement.",
)
