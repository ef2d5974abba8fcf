"""Wells, Problem 4.5 — the Fig. 4-5 chain in (y, y1, y2): absolute heights of m1, m2, and the CM y."""


from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

y, y1, y2 = coordinates("y y1 y2")
m1, m2, m3, k1, k2, l1, l2, g = parameters("m1 m2 m3 k1 k2 l1 l2 g")
M = m1 + m2 + m3

# Y up; m3's height from the CM: m3 y3 = M y − m1 y1 − m2 y2. Springs k1 (m1–m2), k2 (m2–m3).
y3 = (M * y - m1 * y1 - m2 * y2) / m3
system = System(
    [y, y1, y2],
    bodies=[Particle(m1, (0, y1), name="m1"), Particle(m2, (0, y2), name="m2"), Particle(m3, (0, y3), name="m3")],
    forces=(-k1 * (y1 - y2 - l1) * delta(y1 - y2) - k2 * (y2 - y3 - l2) * delta(y2 - y3)
            - g * (m1 * delta(y1) + m2 * delta(y2) + m3 * delta(y3))),
    name="three-mass chain in (y, y1, y2)",
)

br = (m2 + m3) / m3 * y2 + m1 / m3 * y1 - M / m3 * y - l2
PROBLEM = Problem(
    id="p4.5",
    title="Three-mass spring chain in CM and absolute coordinates: generalized forces",
    chapter=4,
    source="Wells, Problem 4.5",
    system=system,
    answers=[
        GeneralizedForces({
            y: -M * g + k2 * M / m3 * br,
            y1: -k1 * (y1 - y2 - l1) - k2 * m1 / m3 * br,
            y2: k1 * (y1 - y2 - l1) - k2 * (m2 + m3) / m3 * br,
        }),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, m3: 1.5, k1: 20, k2: 30, l1: 1, l2: 1, g: 9.81},
                          initial={y: 0, y1: 1.2, y2: 0, y.diff(t): 0, y1.diff(t): 0, y2.diff(t): 0}, t_end=2),
)
