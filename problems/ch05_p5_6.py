"""Wells, Problem 5.6 — uniform bar AB (M, l) pivoted at A with a spring BC to a point C a distance s below A."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

theta = coordinates("theta")
M, g, l, k, s, l0 = parameters("M g l k s l0")

# Bar from the pivot A (origin) at angle theta from the downward vertical; C at (0, -s).
B = (l * sp.sin(theta), -l * sp.cos(theta))
cm_height = -l * sp.cos(theta) / 2
spring_len = sp.sqrt(B[0] ** 2 + (B[1] + s) ** 2)
system = System([theta], T=M * l**2 / 3 * theta.diff(t) ** 2 / 2, bodies=[],
                V=M * g * cm_height + k * (spring_len - l0) ** 2 / 2, name="bar pivoted with a spring")


def _period(sys):
    K = sp.diff(sys.V, theta, 2).subs(theta, 0)
    return sp.simplify(2 * sp.pi * sp.sqrt(sys.mass_matrix[0, 0] / K))


PROBLEM = Problem(
    id="p5.6",
    title="Bar pivoted at A with spring BC: V = -Mgl cos(theta)/2 + k[(s^2+l^2-2sl cos theta)^(1/2) - l0]^2/2",
    chapter=5,
    source="Wells, Problem 5.6",
    system=system,
    answers=[
        PotentialEnergy(-M * g * l * sp.cos(theta) / 2
                        + k * (sp.sqrt(s**2 + l**2 - 2 * s * l * sp.cos(theta)) - l0) ** 2 / 2),
        Quantity("small-oscillation period about theta = 0", _period,
                 2 * sp.pi * sp.sqrt((M * l**2 / 3) / (M * g * l / 2 + k * s * l * (1 - l0 / sp.Abs(s - l))))),
    ],
    simulation=Simulation(params={M: 1, g: 9.81, l: 1, k: 20, s: 2, l0: 0.8}, initial={theta: 0.3, theta.diff(t): 0},
                          t_end=5),
    ranges={"l": (0.3, 0.9), "l0": (0.2, 0.5)},
    correction="The period is DERIVED in the catalog (the book asks for it without printing a value); "
    "the bar's T = (M l^2/3) thd^2 / 2 about the pivot.",
)
