"""Wells, Example 4.2 — five masses in a pulley system (Fig. 4-2) with gravity and external forces f1..f5."""

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

q1, q2, q3, q4, s = coordinates("q1 q2 q3 q4 s")
m1, m2, m3, m4, m5, f1, f2, f3, f4, f5, g = parameters("m1 m2 m3 m4 m5 f1 f2 f3 f4 f5 g")

# Figure not available: downward displacements reconstructed in the catalog so that all six printed F_q hold:
# d1 = q1, d2 = q2 − q3, d3 = −q2 − q3, d4 = −q4, d5 = −4 q1 + 2 q3 + q4.
masses = (m1, m2, m3, m4, m5)
pulls = (f1, f2, f3, f4, f5)


def pulley_system(d, coords, name):
    bodies = [Particle(mi, (0, -di), name=f"m{i + 1}") for i, (mi, di) in enumerate(zip(masses, d, strict=True))]
    # Every mass: weight m g plus an external force f, both downward: δW = Σ (m_i g + f_i) δd_i.
    work = sum((mi * g + fi) * delta(di) for mi, fi, di in zip(masses, pulls, d, strict=True))
    return System(coords, bodies=bodies, forces=work, name=name)


d_a = (q1, q2 - q3, -q2 - q3, -q4, -4 * q1 + 2 * q3 + q4)
set_a = pulley_system(d_a, [q1, q2, q3, q4], "Fig. 4-2 pulleys in (q1, q2, q3, q4)")
d_b = tuple(di.subs(q3, q1 - s) for di in d_a)
set_b = pulley_system(d_b, [q1, q2, s, q4], "Fig. 4-2 pulleys in (q1, q2, s, q4)")

note = ("Figure not available: the kinematics (downward displacements d1..d5) is the catalog's reconstruction, "
        "chosen consistent with all six printed generalized forces.")
sim = dict(params={m1: 5, m2: 1, m3: 1.2, m4: 0.8, m5: 1, f1: 0, f2: 0, f3: 0, f4: 0, f5: 0, g: 9.81}, t_end=0.5)

PROBLEMS = [
    Problem(
        id="ex4.2",
        title="Five masses on pulleys with gravity and external forces: F_q in (q1, q2, q3, q4)",
        chapter=4,
        source="Wells, Example 4.2",
        system=set_a,
        answers=[GeneralizedForces({
            q1: (m1 * g + f1) - 4 * (m5 * g + f5),
            q2: m2 * g + f2 - (m3 * g + f3),
            q3: -(m2 + m3) * g - f2 - f3 + 2 * (m5 * g + f5),
            q4: m5 * g + f5 - (m4 * g + f4),
        })],
        simulation=Simulation(initial={q: 0 for q in (q1, q2, q3, q4)} | {q.diff(t): 0 for q in (q1, q2, q3, q4)},
                              **sim),
        correction=note,
    ),
    Problem(
        id="ex4.2-alt",
        title="Five masses on pulleys: F_q in (q1, q2, s, q4) — F_q1 changes, F_q2 and F_q4 do not",
        chapter=4,
        source="Wells, Example 4.2 (second coordinate set)",
        system=set_b,
        answers=[GeneralizedForces({
            q1: m1 * g + f1 - (m2 * g + m3 * g + f2 + f3) - 2 * (m5 * g + f5),
            q2: m2 * g + f2 - (m3 * g + f3),
            s: (m2 + m3) * g + f2 + f3 - 2 * (m5 * g + f5),
            q4: m5 * g + f5 - (m4 * g + f4),
        })],
        simulation=Simulation(initial={q: 0 for q in (q1, q2, s, q4)} | {q.diff(t): 0 for q in (q1, q2, s, q4)},
                              **sim),
        correction=note,
    ),
]
