"""Wells, Problem 6.15 — a thin ring (radius R, centre x, y, turned θ) sliding on a rough plane, dry friction f
per unit length:
F_x = −f ∫₀^{2π} [ẋ − Rθ̇ sin(θ+α)] R dα / {[ẋ − Rθ̇ sin(θ+α)]² + [ẏ + Rθ̇ cos(θ+α)]²}^{1/2}, and F_y, F_θ alike.

The System's P = −f R ∫₀^{2π} |v(α)| dα is given in closed form: |v|² = A + B cos(α + δ) with A = V² + R²θ̇²,
B = 2RVθ̇ (V the speed of the centre), and ∫₀^{2π} (A + B cos u)^{1/2} du = 4 (A+B)^{1/2} E(2B/(A+B)), E the
complete elliptic integral of the second kind (parameter m). The book's integrals are evaluated by quadrature.
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem

x, y, theta = coordinates("x y theta")
M, R, f = parameters("M R f")
al = sp.Symbol("alpha", real=True)  # angle of a ring element from the ring's own x axis

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
V = sp.sqrt(xd**2 + yd**2)
w = R * sp.sqrt(thd**2)  # R |θ̇|
P = -4 * f * R * (V + w) * sp.elliptic_e(4 * V * w / (V + w) ** 2)
system = System([x, y, theta], bodies=[Particle(M, (x, y))], T=M * R**2 * thd**2 / 2, P=P,
                name="ring sliding on a rough plane")

ux, uy = xd - R * thd * sp.sin(theta + al), yd + R * thd * sp.cos(theta + al)
speed = sp.sqrt(ux**2 + uy**2)
Fx_book = -f * sp.Integral(ux * R / speed, (al, 0, 2 * sp.pi))

PROBLEM = Problem(
    id="p6.15",
    title="Ring on a rough plane: dry friction integrated around the ring (closed form with E(m))",
    chapter=6,
    source="Wells, Problem 6.15",
    system=system,
    answers=[GeneralizedForces({x: Fx_book})],
    # R|θ̇| < |v| of the centre: no ring point is at rest, where the integrands turn sharply (quadrature)
    ranges={"R": (0.1, 0.2)},
    tags=("slow",),  # over 5 s of CPU to check (30-digit quadrature at random states)
    correction="The book prints F_x (F_y and F_θ follow alike; only F_x is compared, each quadrature costs). The "
    "System's P uses the elliptic closed form (valid for V, θ̇ not both zero); generated code has no elliptic "
    "integral, so there is no simulation. A uniform thin ring (mass M, I = MR²) is assumed for T.",
)
