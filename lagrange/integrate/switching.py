r"""Discontinuous forces: Coulomb friction and other ``sign(u)`` switches.

Wells' dry-friction power function ``P = -μN|v|`` gives the generalized force ``-μN sign(v)``, which
jumps when v changes sign (Wells Ex. 6.1: "the friction reverses when the particle turns back").
A smooth integrator stepping across the jump loses its order and, when the particle should stop,
chatters forever. lagrange offers two documented treatments (``simulate(friction=...)``):

``"events"`` (default, exact)
    Every distinct ``sign(u)`` in the equations gets a switch ``σ = ±1``, frozen within a segment,
    so each segment is smooth and integrated to full accuracy. A terminal event at ``u = 0`` ends the
    segment; the new ``σ`` is chosen from the one-sided flows (Filippov's rule): with
    ``g(σ) = du/dt`` evaluated for ``σ = ±1`` (affine in σ because M q̈ = f is),

    * ``g(+1) > 0``: leave into ``u > 0`` with ``σ = +1``; ``g(-1) < 0``: leave into ``u < 0``;
    * otherwise both flows push back onto ``u = 0``: **sticking** (sliding mode). σ is set to the value
      ``σ* ∈ [-1, 1]`` with ``g(σ*) = 0`` — for a block on a rough surface this is exactly the static
      friction needed to hold it — and the body stays stuck until ``|σ*|`` reaches 1 (the needed
      friction exceeds μN), an event that ends the stick.

    Static and kinetic coefficients are taken equal, as in Wells.

``"regularize"``
    ``sign(u) → u/sqrt(u² + ε²)`` with ``friction_epsilon = ε``: smooth, cheap, approximate (a stuck
    body creeps with speed ~ ε·(driving/friction)); pair with a stiff-capable method (LSODA).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ..codegen.cse import numeric_arguments, rename_map
from ..conventions import t
from ..derive.equations import Equations
from ..errors import IntegrationError

__all__ = ["switching_functions", "regularized_equations", "switched_equations", "run_switched"]

_MAX_SEGMENTS = 100_000


def switching_functions(eqs: Equations) -> list:
    """Distinct arguments ``u`` of ``sign(u)`` in the forcing (sorted for determinism)."""
    atoms = set()
    for e in eqs.forcing:
        atoms |= {a.args[0] for a in e.atoms(sp.sign)}
    return sorted(atoms, key=sp.default_sort_key)


def _replace_in(eqs: Equations, mapping: dict, new_params: tuple = ()) -> Equations:
    def sub(e):
        return e.xreplace(mapping)

    return dataclasses.replace(
        eqs,
        forcing=sp.ImmutableMatrix([sub(e) for e in eqs.forcing]),
        dissipative=tuple(sub(e) for e in eqs.dissipative),
        nonconservative=tuple(sub(e) for e in eqs.nonconservative),
        applied=tuple(sub(e) for e in eqs.applied),
        jacobi_rate=sub(eqs.jacobi_rate),
        parameters=eqs.parameters + tuple(new_params),
    )


def regularized_equations(eqs: Equations, epsilon: float) -> Equations:
    """``sign(u) → u/sqrt(u² + ε²)`` everywhere in the forces."""
    eps = sp.Float(epsilon)
    mapping = {}
    for e in list(eqs.forcing) + list(eqs.nonconservative) + [eqs.jacobi_rate]:
        for a in e.atoms(sp.sign):
            u = a.args[0]
            mapping[a] = u / sp.sqrt(u**2 + eps**2)
    return _replace_in(eqs, mapping)


def switched_equations(eqs: Equations, switches: list) -> tuple[Equations, tuple]:
    """Replace ``sign(u_k)`` by parameters ``sigma_k`` (appended to the parameters)."""
    sigmas = tuple(sp.Symbol(f"_sigma{k}", real=True) for k in range(len(switches)))
    mapping = {sp.sign(u): s for u, s in zip(switches, sigmas)}
    new = _replace_in(eqs, mapping, sigmas)
    # parameters must stay in the order compile expects: user parameters sorted, then the sigmas
    return new, sigmas


def run_switched(model, switches, t_span, z0, t_eval, events, kwargs, with_work):
    """Integrate segment by segment with frozen switches (see the module docstring)."""
    from ..codegen.numeric import compile_equations
    from .run import _state_text

    eqs0 = model.equations
    eqs, sigmas = switched_equations(eqs0, switches)
    base = dict(zip(eqs0.parameters, model.params))
    backend = model.backend if model.backend != "reference" else "python"
    sw_model = compile_equations(eqs, {**base, **{s: 1.0 for s in sigmas}}, backend=backend)
    n = eqs.n
    n2 = 2 * n
    K = len(switches)
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)  # switched eqs carry the σ's among their parameters
    # switching functions may contain parameters (a belt speed): evaluated with the σ-free parameter values
    p_u = np.concatenate([model.params, np.ones(K)])
    u_raw = sp.lambdify((tt, ys, ps), [u.xreplace(ren) for u in switches], modules="math")
    grads_raw = [
        sp.lambdify((tt, ys, ps), [sp.diff(u, s).xreplace(ren) for s in (*eqs.q, *eqs.qd, t)], modules="math")
        for u in switches
    ]

    def u_fn(t_, y):
        return u_raw(t_, y, p_u)

    grads = [lambda t_, y, _g=g: _g(t_, y, p_u) for g in grads_raw]
    pw = None
    if with_work:
        pw = sp.lambdify((tt, ys, ps, list(eqs.multipliers)), eqs.jacobi_rate.xreplace(ren), modules="math",
                         cse=True)
    rhs = sw_model.rhs
    nparam = len(eqs0.parameters)

    def deriv(t_, y, p):
        return np.asarray(rhs(t_, y, p), dtype=float)

    def g_of(k, t_, y, p):
        gr = grads[k](t_, list(y))
        return float(np.dot(gr[:n2], deriv(t_, y, p)) + gr[n2])

    def sliding_sigma(t_, y, p, k):
        pm, pp = p.copy(), p.copy()
        pm[nparam + k], pp[nparam + k] = -1.0, 1.0
        gm, gp = g_of(k, t_, y, pm), g_of(k, t_, y, pp)
        if gp == gm:
            return None, gm, gp
        return -1.0 - 2.0 * gm / (gp - gm), gm, gp

    t0, t1 = t_span
    scale = 1.0 + float(np.max(np.abs(z0[:n2])))
    tiny = 1e-9 * scale
    out_t, out_z, out_sig = [], [], []
    user_events = list(events) if events is not None else []
    t_events = [[] for _ in user_events]
    y_events = [[] for _ in user_events]
    nfev = 0
    t_cur, z_cur = t0, np.array(z0, dtype=float)
    sigma = np.ones(K)
    sliding = [False] * K
    segments = 0
    while True:
        segments += 1
        if segments > _MAX_SEGMENTS:
            raise IntegrationError(
                f"more than {_MAX_SEGMENTS} friction switches before t={t_cur:.9g}: the motion chatters; "
                "use friction='regularize'",
                t=float(t_cur),
            )
        y = z_cur[:n2]
        p = np.concatenate([model.params, sigma])
        u = u_fn(t_cur, list(y))
        for k in range(K):
            if abs(u[k]) > tiny:
                sigma[k], sliding[k] = math.copysign(1.0, u[k]), False
                p[nparam + k] = sigma[k]
                continue
            p[nparam + k] = 1.0
            gp = g_of(k, t_cur, y, p)
            p[nparam + k] = -1.0
            gm = g_of(k, t_cur, y, p)
            if gp > 0 and not gm > 0:
                sigma[k], sliding[k] = 1.0, False
            elif gm < 0 and not gp < 0:
                sigma[k], sliding[k] = -1.0, False
            elif gp > 0 and gm > 0:
                sigma[k], sliding[k] = 1.0, False
            elif gp < 0 and gm < 0:
                sigma[k], sliding[k] = -1.0, False
            else:
                sliding[k] = True
            p[nparam + k] = sigma[k]
        seg_sliding = list(sliding)

        def params_at(t_, y_, _p=p, _sl=seg_sliding):
            if not any(_sl):
                return _p
            q = _p.copy()
            for k in range(K):
                if _sl[k]:
                    s, _, _ = sliding_sigma(t_, y_, q, k)
                    q[nparam + k] = 0.0 if s is None else max(-1.0, min(1.0, s))
            return q

        def f(t_, z, _pa=params_at):
            y_ = z[:n2]
            pp = _pa(t_, y_)
            d = list(rhs(t_, y_, pp))
            if pw is not None:
                d.append(pw(t_, list(y_), list(pp), []))
            s = sum(d)
            if s != s or s in (math.inf, -math.inf):
                raise IntegrationError(
                    f"non-finite derivative at t={t_:.9g} ({_state_text(sw_model, z)})", t=float(t_)
                )
            return d

        seg_events = []
        for k in range(K):
            if seg_sliding[k]:
                def ev(t_, z, k=k, _pa=params_at):
                    s, _, _ = sliding_sigma(t_, z[:n2], _pa(t_, z[:n2]), k)
                    return 1.0 - abs(0.0 if s is None else s) - 1e-12
            else:
                def ev(t_, z, k=k):
                    return u_fn(t_, list(z[:n2]))[k]
                ev.direction = -sigma[k]
            ev.terminal = True
            seg_events.append(ev)
        all_events = seg_events + user_events
        mask = (t_eval > t_cur) if out_t else (t_eval >= t_cur)
        te = t_eval[mask & (t_eval <= t1)]
        res = solve_ivp(f, (t_cur, t1), z_cur, t_eval=te, events=all_events or None, **kwargs)
        nfev += res.nfev
        if res.status == -1:
            from .run import _collapse_error

            raise _collapse_error(sw_model, res, t_cur, z_cur[:n2])
        ys = np.asarray(res.y, dtype=float).reshape(len(z_cur), len(res.t))  # [] when no t_eval point inside
        for ti, zi in zip(res.t, ys.T):
            out_t.append(ti)
            out_z.append(zi)
            out_sig.append(params_at(ti, zi[:n2])[nparam:].copy())
        if res.status == 0:
            break
        # which event fired?
        fired = None
        for j, tev in enumerate(res.t_events):
            if len(tev):
                if j >= K:
                    t_events[j - K].extend(tev)
                    y_events[j - K].extend(res.y_events[j])
                    if getattr(user_events[j - K], "terminal", False):
                        fired = "user"
                else:
                    fired = fired or ("switch", j, tev[-1], res.y_events[j][-1])
        if fired == "user" or fired is None:
            break
        _, k, tev, zev = fired
        t_cur, z_cur = float(tev), np.array(zev, dtype=float)
        if t_cur >= t1:
            break
    T = np.array(out_t)
    Z = np.array(out_z).reshape(len(out_t), -1)
    res_obj = _Result(T, Z.T, nfev, t_events, y_events)
    res_obj.sigma = np.array(out_sig).reshape(len(out_t), K)
    res_obj.switched_model = sw_model
    return res_obj


@dataclasses.dataclass
class _Result:
    t: np.ndarray
    y: np.ndarray
    nfev: int
    t_events: list
    y_events: list
    status: int = 0
    message: str = "The solver successfully reached the end of the integration interval."
    success: bool = True
    sigma: np.ndarray | None = None
    switched_model: object = None

    def __post_init__(self):
        self.t_events = [np.array(v) for v in self.t_events]
        self.y_events = [np.array(v) for v in self.y_events]
