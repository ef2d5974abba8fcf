"""Wells, Problem 6.24 — the power function of dry friction f per unit area under a plate sliding on a rough plane,
P = −∫∫ f |v| dA (the plate of Ex. 6.5), for a uniform disc of radius R (x, y its centre, θ its turn).

The System writes the integral over polar body coordinates (ρ, α) about the centre, ρ innermost, with the
element's body coordinates (ρ cos α, ρ sin α); the book's P is compared in its ring form (Prob. 6.15, 6.23:
angle θ + α, α innermost) summed over the rings — the same area parametrized otherwise. sympy finds no
closed form: the integral stays symbolic (lagrange.Quadrature) and generated code evaluates it by Gauss–Legendre
quadrature. Its derivatives are the published closed forms of the sliding-and-spinning disc (Farkas, Bartels,
Unger & Wolf 2003; ``_common.spinning_disc_friction``): F_x = −fπR² 𝓕(ε) ẋ/v and F_θ = −fπR³ 𝓣(ε) sign θ̇,
ε = v/(R|θ̇|).
"""

import sympy as sp
from lagrange_problems._common import spinning_disc_friction

from lagrange import Particle, Quadrature, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, f, R = parameters("M f R")
rho, al = sp.symbols("rho alpha", real=True)  # polar body coordinates of an element

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)


def speed(u, w):
    """|v| of the element at body coordinates (u, w)."""
    vx = xd - thd * (u * sp.sin(theta) + w * sp.cos(theta))
    vy = yd + thd * (u * sp.cos(theta) - w * sp.sin(theta))
    return sp.sqrt(vx**2 + vy**2)


P = -f * Quadrature(speed(rho * sp.cos(al), rho * sp.sin(al)) * rho, (rho, 0, R), (al, 0, 2 * sp.pi))
system = System([x, y, theta], bodies=[Particle(M, (x, y))], T=M * R**2 / 4 * thd**2, P=P,
                name="disc sliding and spinning on a rough plane")

# the book's ring form (Prob. 6.15, 6.23) summed over the rings: angle from the ring's own axis, α innermost
ring = sp.sqrt((xd - rho * thd * sp.sin(theta + al)) ** 2 + (yd + rho * thd * sp.cos(theta + al)) ** 2)
P_book = -f * sp.Integral(ring * rho, (al, 0, 2 * sp.pi), (rho, 0, R))

v = sp.sqrt(xd**2 + yd**2)
Fc, Tc = spinning_disc_friction(v / (R * sp.Abs(thd)))
N = f * sp.pi * R**2  # μN: friction per unit area times the area
closed = GeneralizedForces({x: -N * Fc * xd / v, theta: -N * R * Tc * sp.sign(thd)})

PROBLEM = Problem(
    id="p6.24",
    title="Disc on a rough plane: P = −∫∫ f|v| dA (quadrature), and the sliding-spinning closed forms",
    chapter=6,
    source="Wells, Problem 6.24; Farkas et al., Phys. Rev. Lett. 90, 248302 (2003)",
    system=system,
    answers=[PowerFunction(P_book), closed],
    # R|θ̇| < v: the instantaneous centre outside the disc, where the quadrature of the book's integral is
    # sharp (tests/test_quadrature.py checks ε < 1, the centre inside, against the closed forms)
    ranges={"R": (0.1, 0.2)},
    simulation=Simulation(
        params={M: 1, f: 1, R: 0.5},
        initial={x: 0, y: 0, theta: 0, x.diff(t): 0.5, y.diff(t): 0.0, theta.diff(t): 3.0},
        t_end=0.3,
    ),
    correction="The book states P for a plate of any shape; a uniform disc (T = ½Mv² + ¼MR²θ̇²) is taken, whose "
    "friction force and torque have published closed forms, added as a second answer.",
)
