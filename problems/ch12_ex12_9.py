"""Wells, Example 12.9 — bead sliding down a rough parabolic wire y = b x² (Y up) with gravity and an applied
force F = (F_x, F_y); Coulomb friction μ f opposite the sliding velocity (Fig. 12-6)."""

import sympy as sp

from lagrange import Force, Particle, Rough, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Quantity, Simulation

x, y = coordinates("x y")
m, g, b, mu, Fx, Fy = parameters("m g b mu F_x F_y")

nrm = sp.sqrt(1 + 4 * b**2 * x**2)  # |grad(y - b x^2)| on the wire; cos(theta) = 1/nrm, sin(theta) = 2 b x/nrm
system = System(
    [x, y],
    bodies=[Particle(m, (x, y), name="bead")],
    V=m * g * y,
    forces=[Force(at=(x, y, 0), vector=(Fx, Fy, 0))],
    # sliding velocity = speed along the wire in the +x sense; normal converts lambda to |f|
    constraints=[Rough(y - b * x**2, mu, (x.diff(t) + 2 * b * x * y.diff(t)) / nrm, name="wire", normal=nrm)],
    name="bead on a rough parabolic wire",
)

# Sliding down the x > 0 branch (xd < 0), staying in x > mu/(2b) where the book's f formula is regular.
PARAMS = {m: 1.0, g: 9.81, b: 0.5, mu: 0.2, Fx: 0.5, Fy: -1.0}
INIT = {x: 2.0, y: 2.0, x.diff(t): -0.5, y.diff(t): -1.0}
T_END = 0.5

# --- sign conventions -------------------------------------------------------------------------------------
# Book (1): m xdd = mu f cos(theta) - f sin(theta) + F_x,  m ydd = mu f sin(theta) + f cos(theta) - m g + F_y:
# the normal force f acts along (-sin, cos) = grad(phi)/|grad(phi)| with phi = y - b x^2, the friction mu f along
# +x (the bead slides down, xd < 0). The engine's constraint force is lambda * grad(phi) = lambda * nrm * (unit
# normal), so lambda = f / nrm (f > 0 along the run: the wire is concave up and pushes the bead upward), and
# the engine friction -mu |lambda| nrm sign(v) (unit tangent) equals the book's +mu f (unit tangent) for v < 0.


def _xdd_sliding_down(s):
    """x'' from the engine's multiplier equations with the book's assumptions sign(lambda) = +1 (f > 0) and
    sign(v_sliding) = -1 (sliding down), the wire y = b x^2 imposed and lambda eliminated."""
    lams = set(s.derived.multipliers)
    eqs = [e for e in s.equations()[:2]]
    xdd, ydd = x.diff(t, 2), y.diff(t, 2)
    out = []
    for e in eqs:
        r = (e.lhs - e.rhs).replace(lambda a: isinstance(a, sp.sign),
                                    lambda a: sp.S.One if a.args[0] in lams else -sp.S.One)
        r = r.subs(ydd, 2 * b * x.diff(t) ** 2 + 2 * b * x * xdd).subs(y.diff(t), 2 * b * x * x.diff(t)).subs(y, b * x**2)
        out.append(r)
    (lm,) = lams
    sol = sp.solve(out, [xdd, lm], dict=True)[0]
    return sol[xdd]


# Book's equation of motion: m xdd (1 + 4b^2x^2) + 4 m b^2 x xd^2 = 2 mu b m xd^2 + F_x + mu(m g - F_y)
#                                                                    + 2 b x (mu F_x - m g + F_y)
book_rhs = (2 * mu * b * m * x.diff(t) ** 2 + Fx + mu * (m * g - Fy) + 2 * b * x * (mu * Fx - m * g + Fy))
book_lhs = m * x.diff(t, 2) * (1 + 4 * b**2 * x**2) + 4 * m * b**2 * x * x.diff(t) ** 2
book_xdd = (book_rhs - 4 * m * b**2 * x * x.diff(t) ** 2) / (m * (1 + 4 * b**2 * x**2))
# Book's normal force: f = (m xdd - F_x) sqrt(1 + 4b^2x^2) / (mu - 2 b x);  lambda = f / nrm.
f_book = (m * x.diff(t, 2) - Fx) * nrm / (mu - 2 * b * x)
# Second Newton equation of (1), solved for f: f = (m ydd + m g - F_y) nrm / (1 + 2 mu b x).
f_from_y = (m * y.diff(t, 2) + m * g - Fy) * nrm / (1 + 2 * mu * b * x)

PROBLEM = Problem(
    id="ex12.9",
    title="Bead sliding down a rough parabolic wire y = b x^2: equation of motion and normal force f (Coulomb friction)",
    chapter=12,
    source="Wells, Example 12.9 (Fig. 12-6)",
    system=system,
    answers=[
        Quantity("x'' while sliding down (f > 0, xd < 0)", _xdd_sliding_down, book_xdd,
                 description="book's equation of motion solved for xdd vs the engine's multiplier equations"),
        ConstraintForce("wire", f_book / nrm, PARAMS, INIT, T_END,
                        description="normal force f = (m xdd - F_x) sqrt(1+4b^2x^2)/(mu - 2bx); lambda = f/nrm"),
        # The book's equation of motion along the simulated motion: lambda equals the y-equation reaction plus the
        # residual of the book's equation (any misfit of the equation shows up as a mismatch here).
        ConstraintForce("wire", (f_from_y + (book_lhs - book_rhs)) / nrm, PARAMS, INIT, T_END,
                        description="book's equation of motion along the simulated motion (residual must vanish)"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=T_END),
    correction=("Sign convention: phi = y - b x^2, lambda = f/sqrt(1+4b^2x^2) with f > 0 the book's normal force "
                "(along (-sin theta, cos theta)); the engine's friction -mu|f| sign(v) along the tangent is the "
                "book's +mu f along +x while the bead slides down (xd < 0). The book's results hold only for that "
                "sliding sense and f > 0 (caveat in the catalog); the checks use x0 = 2, xd0 = -0.5 and stop at "
                "t = 0.5, before x reaches mu/(2b) where the f formula is 0/0. The third check adds the residual of "
                "the book's equation of motion to the reaction from the book's y-equation, so it passes only if the "
                "equation holds along the simulated motion."),
)
