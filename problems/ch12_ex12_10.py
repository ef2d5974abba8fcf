"""Wells, Example 12.10 — uniform rod (length 2l, mass M, inertia I about its c.m.) sliding inside a rough
circular cylinder of radius R (Fig. 12-7): both ends on the cylinder, Coulomb friction mu f_1, mu f_2."""

import sympy as sp

from lagrange import Holonomic, Rough, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, Problem, Quantity, Simulation

r, th, al = coordinates("r theta alpha")
M, g, I, mu, R, beta = parameters("M g I mu R beta")

# Geometry: r = R cos(beta) (axis to the rod's c.m.), l = R sin(beta) (half length); theta = angle of the c.m.
# from the downward vertical (Y up), alpha = direction of the rod from the X axis (alpha = theta on the cylinder).
l = R * sp.sin(beta)
r0 = R * sp.cos(beta)
c = sp.Matrix([r * sp.sin(th), -r * sp.cos(th)])
u = sp.Matrix([sp.cos(al), sp.sin(al)])
end1, end2 = c - l * u, c + l * u  # end 1 lags in the +theta sense (the f_1 of the book's eqs. (2), (3))


def _dist(e):
    return sp.sqrt(e[0] ** 2 + e[1] ** 2)


def _tangential(e):
    # velocity of the end along the cylinder (counterclockwise = +theta sense); linear in the velocities
    ed = e.diff(t)
    return (e[0] * ed[1] - e[1] * ed[0]) / _dist(e)


T = sp.Rational(1, 2) * M * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2) + sp.Rational(1, 2) * I * al.diff(t) ** 2
V = -M * g * r * sp.cos(th)


def _system(rough):
    if rough:
        cons = [Rough(_dist(end1) - R, mu, _tangential(end1), name="end1"),
                Rough(_dist(end2) - R, mu, _tangential(end2), name="end2")]
    else:
        cons = [Holonomic(_dist(end1) - R, name="end1"), Holonomic(_dist(end2) - R, name="end2")]
    return System([r, th, al], T=T, V=V, constraints=cons,
                  name="rod inside a " + ("rough" if rough else "smooth") + " cylinder")


rough = _system(True)
smooth = _system(False)
smooth_reduced = eliminate(smooth, {r: r0, al: th})

# --- sign conventions -------------------------------------------------------------------------------------
# phi_i = |end_i| - R is a signed distance (normal = 1), grad(phi_i) = outward radial unit vector at end i.
# The cylinder pushes the ends inward with f_i > 0, so lambda_i = -f_i. The rod slides down with thetad < 0
# (started at theta0 > 0 moving toward the bottom): the sliding velocities are negative and friction acts
# in the +theta sense, as in the book's (2) (+mu r (f_1 + f_2) cos(beta)).
PARAMS = {M: 1.0, g: 9.81, I: 0.0766, mu: 0.3, R: 1.0, beta: 0.5}  # I = M (2l)^2/12 with l = sin(0.5)
_r0 = float(sp.cos(0.5))
INIT = {r: _r0, th: 1.0, al: 1.0, r.diff(t): 0.0, th.diff(t): -0.5, al.diff(t): -0.5}
T_END = 0.4


def _thdd_sliding_down(s):
    """theta'' from the engine's multiplier equations with f_i > 0 (sign(lambda_i) = -1), sliding in the
    -theta sense (sign(v_i) = -1), the constraints r = R cos(beta), alpha = theta imposed, lambdas eliminated."""
    lams = list(s.derived.multipliers)
    res = []
    for e in s.equations()[:3]:
        q = (e.lhs - e.rhs).replace(lambda a: isinstance(a, sp.sign), lambda a: -sp.S.One)
        q = q.subs({r.diff(t, 2): 0, al.diff(t, 2): th.diff(t, 2)}).subs({r.diff(t): 0, al.diff(t): th.diff(t)})
        q = q.subs({r: r0, al: th})
        # the end distances sqrt(r^2 + l^2 ...) reduce to R on the cylinder
        q = q.replace(lambda a: a.is_Pow and a.exp.is_Rational and a.exp.q == 2,
                      lambda a: sp.Pow(sp.factor(sp.expand(sp.expand(a.base).subs(sp.sin(beta) ** 2, 1 - sp.cos(beta) ** 2))), a.exp))
        res.append(q)
    A, rhs = sp.linear_eq_to_matrix(res, [th.diff(t, 2), *lams])
    return sp.cancel(sp.together(A.LUsolve(rhs)[0]))


rr = r0  # the book's r (constant on the cylinder)
wd = th.diff(t)
# Corrected derived equation of motion (see correction): book's (1) with -mu(f_1 - f_2) sin(beta)
thdd_corrected = (2 * M * l * (g * mu * sp.cos(th) + mu * rr * wd**2
                               - g * sp.sin(th) * (1 - sp.sin(beta) ** 2 - mu**2 * sp.sin(beta) ** 2))
                  / (I * (1 + mu**2) * sp.sin(2 * beta) + 2 * M * l * rr * (sp.cos(beta) ** 2 - mu**2 * sp.sin(beta) ** 2)))

# Book (2): M r^2 thdd + M g r sin(theta) = mu r (f1 + f2) cos(beta) + r (f1 - f2) sin(beta)
# Book (3): I alphadd = mu l (f1 + f2) sin(beta) - l (f1 - f2) cos(beta), alphadd = thdd.
# Solved for S = f1 + f2, D = f1 - f2 (determinant -mu): with P = M r thdd + M g sin(theta), Q = I thdd / l,
#   S = (P cos(beta) + Q sin(beta)) / mu,  D = P sin(beta) - Q cos(beta).
P_ = M * rr * th.diff(t, 2) + M * g * sp.sin(th)
Q_ = I * th.diff(t, 2) / l
S_ = (P_ * sp.cos(beta) + Q_ * sp.sin(beta)) / mu
D_ = P_ * sp.sin(beta) - Q_ * sp.cos(beta)
f1_book, f2_book = (S_ + D_) / 2, (S_ - D_) / 2

# mu = 0: (1) (f1 + f2) cos(beta) = M r thd^2 + M g cos(theta), (3) I thdd = -l (f1 - f2) cos(beta)
S0 = (M * rr * wd**2 + M * g * sp.cos(th)) / sp.cos(beta)
D0 = -I * th.diff(t, 2) / (l * sp.cos(beta))
PARAMS0 = {k: v for k, v in PARAMS.items() if k != mu}  # the smooth system has no mu
INIT0 = {r: _r0, th: 1.0, al: 1.0, r.diff(t): 0.0, th.diff(t): 0.0, al.diff(t): 0.0}

RANGES = {"beta": (0.2, 1.2), "mu": (0.1, 0.6)}
CORR = ("The catalog prints (1) M r thd^2 + M g cos(theta) = (f1 + f2) cos(beta) + mu (f1 - f2) sin(beta) and derives "
        "thdd = 2Ml[g mu cos(theta) + mu r thd^2 - g sin(theta)(1 - sin^2 beta + mu^2 sin^2 beta)] / [I(1 - mu^2) "
        "sin 2beta + 2Mlr(cos^2 beta + mu^2 sin^2 beta)] from (1)-(3). With the labelling and friction sense fixed "
        "by the book's (2) and (3), the radial component of the friction at the two ends is +mu sin(beta)(f1 - f2) "
        "outward (the tangent at end 1 points away from the axis, at end 2 toward it), so (1) must read "
        "(f1 + f2) cos(beta) - mu (f1 - f2) sin(beta): no relabelling of f1/f2 or of the angle senses makes the "
        "printed (1) consistent with (2) and (3). Re-solving gives the corrected thdd = 2Ml[g mu cos(theta) + mu r "
        "thd^2 - g sin(theta)(1 - sin^2 beta - mu^2 sin^2 beta)] / [I(1 + mu^2) sin 2beta + 2Mlr(cos^2 beta - mu^2 "
        "sin^2 beta)], which is used (same mu = 0 limit, the compound pendulum). Checked independently: the "
        "torque about the axis gives (I + M r^2) thdd = -M g r sin(theta) + mu R (f1 + f2). The book's (2) and (3) "
        "are used as printed for f1, f2 along the simulated motion. Signs: phi_i = |end_i| - R (signed distance), "
        "lambda_i = -f_i (the cylinder pushes inward); the rod slides in the -theta sense (theta0 = 1, thd0 = -0.5), "
        "friction in the +theta sense as in the book's (2). The catalog's thdd formula is derived, not printed.")

PROBLEMS = [
    Problem(
        id="ex12.10",
        title="Rod sliding inside a rough cylinder: thdd (corrected) and the end reactions f_1, f_2 from (2)-(3)",
        chapter=12,
        source="Wells, Example 12.10 (Fig. 12-7), eqs. (1)-(3)",
        system=rough,
        answers=[
            Quantity("thdd while sliding down (f_i > 0, thd < 0)", _thdd_sliding_down, thdd_corrected,
                     description="derived equation of motion (corrected) vs the engine's rough-constraint equations"),
            ConstraintForce("end1", -f1_book, PARAMS, INIT, T_END, description="f_1 from (2), (3); lambda_1 = -f_1"),
            ConstraintForce("end2", -f2_book, PARAMS, INIT, T_END, description="f_2 from (2), (3); lambda_2 = -f_2"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT, t_end=T_END),
        ranges=RANGES,
        correction=CORR,
    ),
    Problem(
        id="ex12.10-smooth",
        title="Rod inside a smooth cylinder (mu = 0): end reactions f_1, f_2 from (1) and (3)",
        chapter=12,
        source="Wells, Example 12.10, eqs. (1), (3) with mu = 0",
        system=smooth,
        answers=[
            ConstraintForce("end1", -(S0 + D0) / 2, PARAMS0, INIT0, 2.0, description="f_1 (mu = 0); lambda_1 = -f_1"),
            ConstraintForce("end2", -(S0 - D0) / 2, PARAMS0, INIT0, 2.0, description="f_2 (mu = 0); lambda_2 = -f_2"),
        ],
        simulation=Simulation(params=PARAMS0, initial=INIT0, t_end=3.0),
        ranges=RANGES,
        correction="mu = 0 limit of Example 12.10 (the book's (1) sign question does not arise at mu = 0). "
                   "lambda_i = -f_i: the cylinder pushes the ends toward the axis.",
    ),
    Problem(
        id="ex12.10-smooth-reduced",
        title="Rod inside a smooth cylinder, r and alpha eliminated: compound pendulum (I + M r^2) thdd = -M g r sin(theta)",
        chapter=12,
        source="Wells, Example 12.10, mu = 0 limit of the derived equation of motion",
        system=smooth_reduced,
        answers=[
            EquationsOfMotion([sp.Eq((I + M * r0**2) * th.diff(t, 2), -M * g * r0 * sp.sin(th))], per_equation=True),
        ],
        simulation=Simulation(params=PARAMS0, initial={th: 1.0, th.diff(t): 0.0}, t_end=3.0),
        ranges=RANGES,
        correction="mu = 0 limit of the catalog's derived thdd (the book states only the general form); r = R cos(beta).",
    ),
]
