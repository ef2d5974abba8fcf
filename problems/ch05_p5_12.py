"""Wells, Problem 5.12 — five beads on a stretched string (tension tau, spacing a): V for small transverse y."""


from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Simulation

ys = list(coordinates("y1 y2 y3 y4 y5"))
m, tau, a = parameters("m tau a")

# Each string segment is stretched by (Δy)^2/(2a) to second order: work against tension tau.
chain = [0, *ys, 0]
V = sum(tau * ((chain[r + 1] - chain[r]) ** 2) / (2 * a) for r in range(6))
system = System(ys, bodies=[Particle(m, (0, q)) for q in ys], V=V, name="beaded string")

y1, y2, y3, y4, y5 = ys
PROBLEM = Problem(
    id="p5.12",
    title="Five beads on a string: V = (tau/a)[y1^2+...+y5^2 - y1y2 - y2y3 - y3y4 - y4y5]",
    chapter=5,
    source="Wells, Problem 5.12",
    system=system,
    answers=[
        PotentialEnergy(tau / a * (y1**2 + y2**2 + y3**2 + y4**2 + y5**2 - y1 * y2 - y2 * y3 - y3 * y4 - y4 * y5)),
    ],
    simulation=Simulation(params={m: 1, tau: 10, a: 0.5},
                          initial={**{q: 0.0 for q in ys}, y3: 0.1, **{q.diff(t): 0.0 for q in ys}}, t_end=5),
    correction="The system's V is the book's general form (1/2) sum (tau/a)(y_{r+1} - y_r)^2 with y0 = y6 = 0; "
    "the check is its expansion for five beads.",
)
