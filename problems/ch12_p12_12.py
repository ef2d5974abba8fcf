"""Wells, Problem 12.12 — bead on a rough vertical circular loop of radius a (Coulomb friction mu f).

Polar coordinates (r, theta) about the centre, theta from the upward vertical, so the bead is at
(r sin theta, r cos theta) with Y up; the wire is r = a (phi = r - a, a signed distance, so the multiplier is the
normal force f, positive outward). For one sliding sense (theta-dot > 0) and an outward normal force (f > 0) the
equations of the multiplier method give

    m a theta'' - m g sin theta = mu (m a theta'^2 - m g cos theta),     f = m g cos theta - m a theta'^2,

which the problem checks (the catalog's derived form). The book's printed answer is an OCR-doubtful Cartesian form
whose mu = 0 limit is wrong; it is not used (see ``correction``).
"""

import sympy as sp

from lagrange import Particle, Rough, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

r, th = coordinates("r theta")
m, g, a, mu = parameters("m g a mu")
system = System(
    [r, th],
    bodies=[Particle(m, (r * sp.sin(th), r * sp.cos(th)), name="bead")],
    V=m * g * r * sp.cos(th),
    constraints=[Rough(r - a, mu, r * th.diff(t), name="loop")],
    name="bead on a rough vertical loop",
)

ON_LOOP = {r.diff(t, 2): 0, r.diff(t): 0}


def _solved(s):
    """theta'' and the multiplier from the engine's equations with sign(lambda) = +1 (f outward) and
    sign(sliding) = +1 (theta increasing), on the loop r = a."""
    lams = set(s.derived.multipliers)
    (lm,) = lams
    eqs = []
    for e in s.equations()[:2]:
        res = (e.lhs - e.rhs).replace(lambda z: isinstance(z, sp.sign), lambda z: sp.S.One)
        eqs.append(res.subs(ON_LOOP).subs(r, a))
    sol = sp.solve(eqs, [th.diff(t, 2), lm], dict=True)[0]
    return [sol[th.diff(t, 2)], sol[lm]]


thd = th.diff(t)
f_derived = m * g * sp.cos(th) - m * a * thd**2
thdd_derived = (m * g * sp.sin(th) + mu * (m * a * thd**2 - m * g * sp.cos(th))) / (m * a)

PROBLEM = Problem(
    id="p12.12",
    title="Bead on a rough vertical loop: m a theta'' - m g sin theta = mu (m a theta'^2 - m g cos theta)",
    chapter=12,
    source="Wells, Problem 12.12",
    system=system,
    answers=[Quantity("theta'' and the outward normal force f (theta' > 0, f > 0)", _solved,
                      [thdd_derived, f_derived])],
    correction="The printed answer (as transcribed), m(y'' + g)(x - mu y) = m x''(mu x - y), has a wrong smooth limit: "
    "at mu = 0 it gives x(y'' + g) = -y x'', but the tangent (y, -x) of the loop requires x(y'' + g) = y x''. The "
    "corrected form (centre at the origin, Y up, outward normal force, one sliding sense) is m(y'' + g)(x - mu y) "
    "= m x''(mu x + y); its polar form, m a theta'' - m g sin theta = mu(m a theta'^2 - m g cos theta) with theta "
    "from the upward vertical, is what is checked.",
)
