"""Rough constraints (Wells 12.5): friction proportional to the unknown normal reaction.

Within a segment the friction sign ``σ_k = sign(λ_k)·sign(v_s,k)`` of each rough constraint is fixed,
so the reaction enters linearly (``M q̈ = f + Bλ``, B built in :mod:`lagrange.derive.multipliers`) and
the segment is smooth. A segment ends when

* a normal reaction λ_k changes sign: σ_k flips and integration continues, or
* a sliding velocity reaches zero: the integration stops there with a message — sticking (static
  friction) on a rough constraint is not modelled, as in Wells, whose results hold "only while the assumed
  sliding direction and the sign of f hold".

At the start of each segment σ is chosen self-consistently (``sign(λ(σ))·sign(v_s) = σ``).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ..codegen.cse import numeric_arguments, rename_map
from ..errors import IntegrationError
from .stepper import step_loop
from .switching import _Result

__all__ = ["run_rough"]

_MAX_SEGMENTS = 10_000


def _sliding_functions(model):
    eqs = model.equations
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)
    exprs = [v.xreplace(ren) for _, v in eqs.sliding_velocities]
    fn = sp.lambdify((tt, ys, ps), exprs, modules="math")
    return lambda t_, y, p: fn(t_, list(y), list(p))


def _choose_signs(model, t0, y, p, vs_fn, kinds):
    """Self-consistent σ for every rough constraint at (t0, y)."""
    eqs = model.equations
    n2 = 2 * eqs.n
    nparam = len(eqs.parameters)
    v = list(vs_fn(t0, y, p))
    scale = 1e-10 * (1.0 + float(np.max(np.abs(y))))
    p = p.copy()
    # --- friction over a surface (sliding function |v| − 1e-9, lagrange.codegen.rough_friction): at rest the
    # direction v/|v| is undefined and starting to slide is not modelled
    planar = {k for k, _ in eqs.planar_friction}
    for i, (k, _) in enumerate(kinds):
        if k in planar and v[i] <= 0:
            raise _Stop(f"{eqs.constraint_names[k]}: at rest at t={t0:.9g} on a rough surface (friction over a "
                        "surface in any direction); starting from rest and sticking are not modelled with "
                        "friction='events', the run ends here (friction='regularize' runs through rest)")
    # --- end of friction over a surface
    for i, (k, _) in enumerate(kinds):
        if k in planar:
            continue
        if abs(v[i]) <= scale:
            v[i] = _starting_direction(model, t0, y, p, vs_fn, i, k)

    for _ in range(4):
        lam = np.asarray(model.dynamics(t0, y, p)[n2:], dtype=float)
        changed = False
        for i, (k, _) in enumerate(kinds):
            want = np.sign(lam[k] if lam[k] != 0 else 1.0) * np.sign(v[i])
            if p[nparam + i] != want:
                p[nparam + i] = want
                changed = True
        if not changed:
            break
    return p


class _Stop(Exception):
    pass


def _starting_direction(model, t0, y, p, vs_fn, i, k) -> float:
    """At rest on rough constraint k: the direction d = ±1 in which it starts sliding with friction
    opposing it (kinetic = static friction), or _Stop when friction holds it in both directions."""
    eqs = model.equations
    n2 = 2 * eqs.n
    nparam = len(eqs.parameters)
    h = 1e-7
    for d in (1.0, -1.0):
        q = p.copy()
        lam = np.asarray(model.dynamics(t0, y, q)[n2:], dtype=float)
        q[nparam + i] = np.sign(lam[k] if lam[k] != 0 else 1.0) * d
        dy = np.asarray(model.dynamics(t0, y, q)[:n2], dtype=float)
        if np.sign(vs_fn(t0 + h, y + h * dy, q)[i]) == d:
            return d
    raise _Stop(f"{eqs.constraint_names[k]}: at rest at t={t0:.9g} and friction holds it in both directions; "
                "sticking (static friction) on a rough constraint is not modelled, the run ends here")


def run_rough(model, f_of, t_span, z0, t_eval, events, kwargs, projector):
    """Integrate segment by segment; ``f_of(model)`` builds the state function for a parameter set."""
    eqs = model.equations
    n2 = 2 * eqs.n
    kinds = eqs.sliding_velocities
    vs_fn = _sliding_functions(model)
    t0, t1 = t_span
    t_cur, z_cur = t0, np.array(z0, dtype=float)
    out_t, out_z, out_p = [], [], []
    user_events = list(events or [])
    t_events = [[] for _ in user_events]
    y_events = [[] for _ in user_events]
    nfev, message = 0, "The solver successfully reached the end of the integration interval."
    p = np.array(model.params, dtype=float)
    for _segment in range(_MAX_SEGMENTS):
        try:
            p = _choose_signs(model, t_cur, z_cur[:n2], p, vs_fn, kinds)
        except _Stop as stop:
            message = str(stop)
            break
        seg_model = dataclasses.replace(model, params=p.copy())

        def ev_slide(t_, z, i=0, m_=seg_model):
            return vs_fn(t_, z[:n2], m_.params)[i]

        def ev_normal(t_, z, k=0, m_=seg_model):
            return float(m_.multipliers(t_, z[:n2])[k])

        seg_events = []
        for i, (k, _) in enumerate(kinds):
            e1 = _bind(ev_slide, i=i)
            e2 = _bind(ev_normal, k=k)
            seg_events += [e1, e2]
        all_events = seg_events + user_events
        f = f_of(seg_model)
        te = t_eval[(t_eval > t_cur) if out_t else (t_eval >= t_cur)]
        te = te[te <= t1]
        if projector is not None:
            res = step_loop(f, (t_cur, t1), z_cur, t_eval=te, events=all_events, post_step=projector, **kwargs)
        else:
            res = solve_ivp(f, (t_cur, t1), z_cur, t_eval=te, events=all_events, **kwargs)
        nfev += res.nfev
        if res.status == -1:
            raise IntegrationError(f"integration failed at t={res.t[-1] if len(res.t) else t_cur:.9g}: {res.message}")
        out_t += list(res.t)
        out_z += list(res.y.T)
        out_p += [p.copy()] * len(res.t)
        for j in range(len(user_events)):
            t_events[j] += list(res.t_events[len(seg_events) + j])
            y_events[j] += list(res.y_events[len(seg_events) + j])
        if res.status == 0:
            break
        fired = [(float(res.t_events[j][0]), j) for j in range(len(seg_events)) if len(res.t_events[j])]
        if not fired:  # a terminal user event
            message = "A termination event occurred."
            break
        te_, j = min(fired)
        z_cur = np.array(res.y_events[j][0], dtype=float)
        t_cur = te_
        if j % 2 == 0:  # sliding velocity reached zero
            k = kinds[j // 2][0]
            message = (f"Sliding stopped on the rough constraint {eqs.constraint_names[k]} at t={t_cur:.9g}; "
                       "sticking (static friction) is not modelled, the run ends here.")
            break
    else:
        raise IntegrationError(f"more than {_MAX_SEGMENTS} friction-sign changes: the normal force chatters")
    if not out_t:  # stopped before the first step: report the state where it stopped
        out_t, out_z, out_p = [t_cur], [z_cur], [p.copy()]
    T = np.array(out_t)
    Z = np.array(out_z).reshape(len(out_t), -1)
    r = _Result(T, Z.T, nfev, t_events, y_events, message=message)
    r.point_params = np.array(out_p).reshape(len(out_t), len(p))
    return r


def _bind(fn, **kw):
    def ev(t_, z):
        return fn(t_, z, **kw)

    ev.terminal = True
    ev.direction = 0
    return ev
