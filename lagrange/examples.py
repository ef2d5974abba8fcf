"""Ready-made systems used by benchmarks, tests and notebooks."""

from __future__ import annotations

import sympy as sp

from .model.bodies import Particle
from .model.coordinates import coordinates, parameters
from .model.system import System

__all__ = ["n_link_pendulum", "andrews_squeezer", "SQUEEZER_DATA", "SQUEEZER_INITIAL", "SQUEEZER_REFERENCE"]


def n_link_pendulum(n: int, *, symbolic: bool = False, **system_kwargs) -> System:
    """Planar pendulum of ``n`` point masses on massless rods, absolute angles from the downward vertical.

    With ``symbolic=False`` (default) masses and lengths are 1 and ``g`` is a parameter, as in
    ``reference/numerics.md``; with ``symbolic=True`` masses ``m_i`` and lengths ``l_i`` are parameters.
    ``system_kwargs`` are passed to :class:`~lagrange.System` as they are (e.g. ``derivation="expanded"``;
    keywords it does not take raise its ``TypeError``); ``name`` defaults to ``"<n>-link pendulum"``.
    """
    if n < 1:
        raise ValueError("n must be at least 1")
    qs = coordinates([f"q{i + 1}" for i in range(n)])
    qs = qs if isinstance(qs, tuple) else (qs,)
    g = parameters("g")
    X, Y = sp.S.Zero, sp.S.Zero
    bodies = []
    V = sp.S.Zero
    for i, q in enumerate(qs):
        if symbolic:
            m, length = parameters(f"m{i + 1} l{i + 1}")
        else:
            m, length = sp.S.One, sp.S.One
        X += length * sp.sin(q)
        Y -= length * sp.cos(q)
        bodies.append(Particle(m, (X, Y), name=f"bob{i + 1}"))
        V += m * g * Y
    system_kwargs.setdefault("name", f"{n}-link pendulum")
    return System(list(qs), bodies=bodies, V=V, **system_kwargs)


#: Andrews' squeezing mechanism (SI units): Schiehlen's data as in Hairer & Wanner, *Solving Ordinary
#: Differential Equations II*, §VII.7, and the test set for IVP solvers (Mazzia & Magherini, problem "andrews").
SQUEEZER_DATA = {
    "m1": "0.04325", "m2": "0.00365", "m3": "0.02373", "m4": "0.00706", "m5": "0.07050", "m6": "0.00706",
    "m7": "0.05498", "i1": "2.194e-6", "i2": "4.410e-7", "i3": "5.255e-6", "i4": "5.667e-7", "i5": "1.169e-5",
    "i6": "5.667e-7", "i7": "1.912e-5", "xa": "-0.06934", "ya": "-0.00227", "xb": "-0.03635", "yb": "0.03273",
    "xc": "0.014", "yc": "0.072", "d": "0.028", "da": "0.0115", "e": "0.02", "ea": "0.01421", "rr": "0.007",
    "ra": "0.00092", "ss": "0.035", "sa": "0.01874", "sb": "0.01043", "sc": "0.018", "sd": "0.02",
    "ta": "0.02308", "tb": "0.00916", "u": "0.04", "ua": "0.01228", "ub": "0.00449", "zf": "0.02", "zt": "0.04",
    "fa": "0.01421", "mom": "0.033", "c0": "4530", "l0": "0.07785",
}
#: the consistent initial angles (β, Θ, γ, Φ, δ, Ω, ε) of the test set, at rest
SQUEEZER_INITIAL = (-0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
                    0.222668390165885884674473185609, 0.487364979543842550225598953530,
                    -0.222668390165885884674473185609, 1.23054744454982119249735015568)
#: the test set's reference solution at t = 0.03 (PSIDE at tolerance 1e-14): the angles, then their rates
SQUEEZER_REFERENCE = (
    (0.1581077119629904e2, -0.1575637105984298e2, 0.4082224013073101e-1, -0.5347301163226948,
     0.5244099658805304, 0.5347301163226948, 0.1048080741042263e1),
    (0.1139920302151208e4, -0.1424379294994111e4, 0.1103291221937134e2, 0.1929337464421385e2,
     0.5735699284790808, -0.1929337464421385e2, 0.3231791658026955),
)


def andrews_squeezer(**system_kwargs) -> System:
    r"""Andrews' squeezing mechanism, the seven-body planar benchmark of Schiehlen (1990) and Hairer & Wanner
    (*Solving ODE II*, §VII.7): seven :class:`~lagrange.PlanarBody` s, a tree in the relative angles
    (β, Θ, γ, Φ, δ, Ω, ε) closed by three :func:`~lagrange.revolute` joints (six constraints), driven by the
    torque ``mom`` on the crank K1 and loaded by a spring (``c0``, ``l0``) from point D of K3 to the fixed
    point C. No gravity (the mechanism lies in a horizontal plane).

    The constraints are the published ``g(q) = 0`` in order and sign (the multipliers are minus the test
    set's, whose equation is ``M q̈ = f − Gᵀλ``). Parameters are symbols; their values are
    :data:`SQUEEZER_DATA`, the initial angles :data:`SQUEEZER_INITIAL`, the reference at t = 0.03
    :data:`SQUEEZER_REFERENCE`. ``system_kwargs`` go to :class:`~lagrange.System`.
    """
    from .model.joints import revolute, spring_potential
    from .model.planar import PlanarBody

    beta, Th, gamma, Phi, delta, Om, eps = coordinates("beta Theta gamma Phi delta Omega epsilon")
    P = dict(zip(SQUEEZER_DATA, parameters(list(SQUEEZER_DATA))))
    A, B = (P["xa"], P["ya"]), (P["xb"], P["yb"])
    #        mass      inertia   hinged at           angle        centre of mass                 named points
    table = [("K1", "m1", "i1", (0, 0), beta, (P["ra"], 0), {"P": (P["rr"], 0)}),
             ("K2", "m2", "i2", "K1.P", beta + Th, (-P["da"], 0), {"F": (-P["d"], 0)}),
             ("K3", "m3", "i3", B, gamma, (P["sb"], -P["sa"]), {"F": (0, -P["ss"]), "D": (P["sd"], -P["sc"])}),
             ("K5", "m5", "i5", A, delta, (P["ta"], P["tb"]), {"E": (P["zt"], 0)}),
             ("K4", "m4", "i4", "K5.E", Phi + delta, (0, P["ea"] - P["e"]), {"F": (0, -P["e"])}),
             ("K7", "m7", "i7", A, eps, (-P["ub"], -P["ua"]), {"G": (0, -P["u"])}),
             ("K6", "m6", "i6", "K7.G", Om + eps, (P["zf"] - P["fa"], 0), {"F": (P["zf"], 0)})]
    K: dict = {}
    for name, m, inertia, at, angle, com, points in table:
        at = K[at[:2]].point(at[3:]) if isinstance(at, str) else at
        K[name] = PlanarBody(P[m], P[inertia], at, angle, com=com, points=points, name=name)
    joints = [revolute(K["K2"].point("F"), K[k].point("F")) for k in ("K3", "K4", "K6")]
    system_kwargs.setdefault("name", "Andrews' squeezing mechanism")
    return System([beta, Th, gamma, Phi, delta, Om, eps], bodies=[K[k] for k in sorted(K)], constraints=joints,
                  V=spring_potential(K["K3"].point("D"), (P["xc"], P["yc"]), P["c0"], P["l0"]),
                  forces=[K["K1"].torque(P["mom"])], **system_kwargs)
