r"""Discontinuous forces: Coulomb friction and other ``sign(u)`` switches.

Wells' dry-friction power function ``P = -μN|v|`` gives the generalized force ``-μN sign(v)``, which
jumps when v changes sign (Wells Ex. 6.1: "the friction reverses when the particle turns back").
A smooth integrator stepping across the jump loses its order and, when the particle should stop,
chatters forever. lagrange offers two documented treatments (``simulate(friction=...)``):

``"events"`` (default, exact)
    Every distinct ``sign(u)`` in the equations gets a switch ``σ``, frozen within a segment, so each
    segment is smooth and integrated to full accuracy. Each switch is in one of three modes: **slip±**
    (σ = ±1) or **stick** (σ = σ*, below). With ``g(σ) = du/dt`` (affine in σ because M q̈ = f is) and
    ``σ* = (g(+1) + g(−1)) / (g(−1) − g(+1))`` the σ with ``g(σ*) = 0`` — for a block on a rough surface
    exactly the static friction, in units of μN, needed to hold it — the rules are:

    * **slip±** ends at the terminal event ``u = 0`` (crossed towards the surface). The new mode is
      chosen there from the one-sided flows (Filippov's rule): for a friction-like switch
      (``g(+1) < g(−1)``) **stick** if ``|σ*| ≤ 1 + η``, else slip with ``σ = sign σ*`` (the side whose
      flow leaves the surface); otherwise slip+ if ``g(+1) > 0``, slip− if ``g(−1) < 0``, else stick.
    * **stick** holds ``u`` fixed with ``σ = σ*`` and ends at the terminal event ``|σ*| = 1 + η`` (the
      friction needed exceeds what is available). The switch then slips with ``σ = sign σ*`` *without*
      re-testing Filippov's rule: at that event the test would compare two numbers that are zero up to
      rounding and could send the body back into sticking at the very same instant.
    * A switch changes mode only at its own event; switches stuck at the same time are solved jointly
      (the σ* of all of them from one small linear system), others keep their σ.
    * At the start, a switch with ``|u| ≤ 1e-9 (1 + max|y0|)`` is on its surface (Filippov's rule
      decides); otherwise it slips with ``σ = sign u``.

    **Hysteresis η = rtol** (the integrator's relative tolerance, at least 100 machine epsilons): static
    friction holds up to (1 + η) μN. It guarantees progress — after a stick ends the body leaves the surface
    with ``σ·du/dt = η (g(−1) − g(+1))/2 > 0``, so the next event cannot fire at the same instant, and a
    body loaded exactly to the friction limit stays stuck instead of switching on rounding noise — and it
    costs O(η²) in the velocity (the stick ends η/(d|σ*|/dt) late while the slip acceleration grows from
    zero). Static and kinetic coefficients are otherwise equal, as in Wells. :attr:`Trajectory.switches`
    holds the σ at the output times (|σ| ≤ 1 + η while stuck) and every mode change
    (:class:`Transition`).

``"regularize"``
    ``sign(u) → u/sqrt(u² + ε²)`` with ``friction_epsilon = ε``: smooth, cheap, approximate (a stuck
    body creeps with speed ~ ε·(driving/friction)); pair with a stiff-capable method (LSODA).
"""

from __future__ import annotations

import dataclasses
import math
import weakref
from typing import NamedTuple

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ..codegen.cse import numeric_arguments, rename_map
from ..conventions import t
from ..derive.equations import Equations
from ..errors import InputError, IntegrationError

__all__ = ["switching_functions", "regularized_equations", "switched_equations", "run_switched", "Transition"]

_MAX_SEGMENTS = 100_000
_STICK = 0  # mode of a stuck switch; slipping modes are σ = ±1
_MODE_NAMES = {1: "slip+", -1: "slip-", _STICK: "stick"}


class Transition(NamedTuple):
    """A mode change of switch ``switch`` (index into :func:`switching_functions`) at time ``t``;
    ``before`` / ``after`` are ``"slip+"``, ``"slip-"`` or ``"stick"`` (``before`` is ``""`` at the start)."""

    t: float
    switch: int
    before: str
    after: str


_SWITCHES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def switching_functions(eqs: Equations) -> list:
    """Distinct arguments ``u`` of ``sign(u)`` in the forcing (sorted for determinism); found once per
    Equations (a tree walk of the forcing costs about 0.1 ms, which repeated short runs would pay each time)."""
    if eqs not in _SWITCHES:
        atoms = set()
        for e in eqs.forcing:
            atoms |= {a.args[0] for a in e.atoms(sp.sign)}
        _SWITCHES[eqs] = tuple(sorted(atoms, key=sp.default_sort_key))
    return list(_SWITCHES[eqs])


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


class _Switched:
    """The numeric pieces of a switched run: the right-hand side with the σ's among its parameters (after
    the ``nparam`` user parameters), the switching functions u_k and their rates g_k = du_k/dt."""

    def __init__(self, model, switches):
        from ..codegen.numeric import compile_equations

        eqs0 = model.equations
        eqs, sigmas = switched_equations(eqs0, switches)
        if model.schedule is not None:
            varying = {u for u, kind in zip(model.schedule.inputs, model.schedule.kinds) if kind != "constant"}
            inside = sorted({str(u) for u in varying for w in switches if u in w.free_symbols})
            if inside:
                raise InputError(f"the dry-friction switch sign() of {', '.join(map(str, switches))} contains the "
                                 f"time-varying input(s) {', '.join(inside)}: locating its sign changes needs the "
                                 "input's rate; use friction='regularize' or a constant input")
        base = dict(zip(eqs0.numeric_parameters, model.params))  # parameters and input constants
        backend = model.backend if model.backend != "reference" else "python"
        self.model = compile_equations(eqs, {**base, **{s: 1.0 for s in sigmas}}, backend=backend)
        self.model = self.model.with_schedule(model.schedule) if model.schedule is not None else self.model
        self.eqs, self.K, self.n2, self.nparam = eqs, len(switches), 2 * eqs.n, len(eqs0.parameters)
        ren = rename_map(eqs)
        tt, ys, ps = numeric_arguments(eqs)  # switched eqs carry the σ's among their parameters
        # switching functions may contain parameters (a belt speed): evaluated with the σ-free parameter values
        self._p_u = np.array(self.model.params, dtype=float)  # σ's at 1, the inputs' constants after them
        self._u = sp.lambdify((tt, ys, ps), [u.xreplace(ren) for u in switches], modules="math")
        grad = [[sp.diff(u, s).xreplace(ren) for s in (*eqs.q, *eqs.qd, t)] for u in switches]
        self._grad = sp.lambdify((tt, ys, ps), grad, modules="math")

    def power_function(self):
        """``(t, y, p, λ) ↦`` power of the non-conservative forces (the work integrand; time-varying inputs at
        their values at (t, y))."""
        tt, ys, ps = numeric_arguments(self.eqs)
        rate = self.eqs.jacobi_rate.xreplace(rename_map(self.eqs))
        f = sp.lambdify((tt, ys, ps, list(self.eqs.multipliers)), rate, modules="math", cse=True)
        schedule = self.model.schedule
        if schedule is None:
            return f
        k0, k = self.eqs.input_offset, len(self.eqs.inputs)

        def power(t_, y, p, lam):
            p = list(p)
            p[k0:k0 + k] = schedule(t_, y)
            return f(t_, y, p, lam)

        return power

    def params_with(self, modes) -> np.ndarray:
        """The parameter vector with the σ's set to ``modes`` (inputs' slots kept)."""
        p = np.array(self.model.params, dtype=float)
        p[self.nparam:self.nparam + self.K] = modes
        return p

    def u(self, t_, y) -> list:
        return self._u(t_, list(y), self._p_u)

    def g(self, t_, y, p) -> np.ndarray:
        """du_k/dt for every switch with the parameters (σ's included) ``p``."""
        gr = np.asarray(self._grad(t_, list(y), self._p_u), dtype=float).reshape(self.K, self.n2 + 1)
        return gr[:, :-1] @ np.asarray(self.model.rhs(t_, y, p), dtype=float) + gr[:, -1]

    def solve_stuck(self, t_, y, p, stuck) -> np.ndarray:
        """``p`` with the σ's of the ``stuck`` switches set to σ*, the values that make all their g_k vanish
        (g is affine in σ: one linear system; the least-squares σ* where it is singular, e.g. g free of σ)."""
        if not stuck:
            return p
        q = np.array(p, dtype=float)
        idx = self.nparam + np.asarray(stuck)
        q[idx] = 0.0
        b = self.g(t_, y, q)[stuck]
        A = np.empty((len(stuck), len(stuck)))
        for j in range(len(stuck)):
            q[idx] = 0.0
            q[idx[j]] = 1.0
            A[:, j] = self.g(t_, y, q)[stuck] - b
        try:
            q[idx] = np.linalg.solve(A, -b)
        except np.linalg.LinAlgError:
            q[idx] = np.linalg.lstsq(A, -b, rcond=None)[0]
        return q

    def decide(self, k, t_, y, p, stuck, eta) -> int:
        """Filippov's rule for switch k on its surface (module docstring), the ``stuck`` others re-solved."""
        gp, gm = (self.g(t_, y, self.solve_stuck(t_, y, _with(p, self.nparam + k, s), stuck))[k] for s in (1, -1))
        if gp < gm:  # friction-like: |σ*| <= 1 + η means static friction can hold
            # σ* exactly as the stick event will evaluate it, so that event starts at a value >= 0
            s_star = self.solve_stuck(t_, y, p, sorted({*stuck, k}))[self.nparam + k]
            return _STICK if abs(s_star) <= 1.0 + eta else int(math.copysign(1.0, s_star))
        if gp > 0:
            return 1
        return -1 if gm < 0 else _STICK


def _with(p, i, value):
    q = np.array(p, dtype=float)
    q[i] = value
    return q


def _initial_modes(sw: _Switched, t0, y0, eta) -> list:
    scale = 1.0 + float(np.max(np.abs(y0)))
    u0 = sw.u(t0, y0)
    modes = [_STICK] * sw.K
    p = sw.params_with(np.ones(sw.K))
    for k in range(sw.K):
        if abs(u0[k]) > 1e-9 * scale:
            modes[k] = int(math.copysign(1.0, u0[k]))
        else:
            others = [j for j in range(k) if modes[j] == _STICK]
            modes[k] = sw.decide(k, t0, y0, p, others, eta)
        p[sw.nparam + k] = modes[k]
    return modes


def _segment_events(sw: _Switched, modes, params_at, eta) -> list:
    """One terminal event per switch: ``u_k = 0`` crossed towards the surface while slipping,
    ``|σ*_k| = 1 + η`` while stuck."""
    events = []
    for k, mode in enumerate(modes):
        if mode == _STICK:
            def ev(t_, z, k=k):
                y = z[: sw.n2]
                return 1.0 + eta - abs(params_at(t_, y)[sw.nparam + k])
            ev.direction = -1.0
        else:
            def ev(t_, z, k=k):
                return sw.u(t_, z[: sw.n2])[k]
            ev.direction = -float(mode)
        ev.terminal = True
        events.append(ev)
    return events


def run_switched(model, switches, t_span, z0, t_eval, events, kwargs, with_work):
    """Integrate segment by segment with frozen switches (see the module docstring)."""
    from .run import _collapse_error

    sw = _Switched(model, switches)
    t0, t1 = t_span
    eta = max(float(kwargs.get("rtol", 1e-3)), 100 * np.finfo(float).eps)
    pw = sw.power_function() if with_work else None
    user_events = list(events) if events is not None else []
    t_events, y_events = [[] for _ in user_events], [[] for _ in user_events]
    out_t, out_z, out_sig = [], [], []
    nfev, t_cur, z_cur = 0, t0, np.array(z0, dtype=float)
    modes = _initial_modes(sw, t0, z_cur[: sw.n2], eta)
    transitions = [Transition(float(t0), k, "", _MODE_NAMES[m]) for k, m in enumerate(modes)]
    for _segment in range(_MAX_SEGMENTS):
        stuck = [k for k in range(sw.K) if modes[k] == _STICK]
        p = sw.params_with(np.array(modes, dtype=float))

        def params_at(t_, y_, _p=p, _stuck=stuck):
            return sw.solve_stuck(t_, y_, _p, _stuck)

        mask = (t_eval > t_cur) if out_t else (t_eval >= t_cur)
        res = solve_ivp(_segment_rhs(sw, params_at, pw), (t_cur, t1), z_cur, t_eval=t_eval[mask & (t_eval <= t1)],
                        events=_segment_events(sw, modes, params_at, eta) + user_events or None, **kwargs)
        nfev += res.nfev
        if res.status == -1:
            raise _collapse_error(sw.model, res, t_cur, z_cur[: sw.n2])
        ys = np.asarray(res.y, dtype=float).reshape(len(z_cur), len(res.t))  # [] when no t_eval point inside
        for ti, zi in zip(res.t, ys.T):
            out_t.append(ti)
            out_z.append(zi)
            out_sig.append(params_at(ti, zi[: sw.n2])[sw.nparam:sw.nparam + sw.K].copy())
        fired, user_stop = _collect_events(res, sw.K, user_events, t_events, y_events)
        if res.status == 0 or user_stop or fired is None:
            break
        k, t_cur, z_cur = fired
        y = z_cur[: sw.n2]
        if modes[k] == _STICK:  # the friction needed exceeds (1 + η) μN: slip the way it pulls, no re-test
            new = int(math.copysign(1.0, params_at(t_cur, y)[sw.nparam + k]))
        else:
            new = sw.decide(k, t_cur, y, p, [j for j in stuck if j != k], eta)
        transitions.append(Transition(t_cur, k, _MODE_NAMES[modes[k]], _MODE_NAMES[new]))
        modes[k] = new
        if t_cur >= t1:
            break
    else:
        raise IntegrationError(
            f"more than {_MAX_SEGMENTS} friction switches before t={t_cur:.9g}: the motion chatters; "
            "use friction='regularize'",
            t=float(t_cur),
        )
    T = np.array(out_t)
    Z = np.array(out_z).reshape(len(out_t), -1)
    res_obj = _Result(T, Z.T, nfev, t_events, y_events)
    res_obj.sigma = np.array(out_sig).reshape(len(out_t), sw.K)
    res_obj.switched_model = sw.model
    res_obj.transitions = tuple(transitions)
    return res_obj


def _segment_rhs(sw: _Switched, params_at, pw):
    """The state derivative of one segment (plus the power of the non-conservative forces when ``pw``)."""
    from .run import _state_text

    n2, rhs = sw.n2, sw.model.rhs

    def f(t_, z):
        y_ = z[:n2]
        pp = params_at(t_, y_)
        d = list(rhs(t_, y_, pp))
        if pw is not None:
            d.append(pw(t_, list(y_), list(pp), []))
        s = sum(d)
        if s != s or s in (math.inf, -math.inf):
            raise IntegrationError(f"non-finite derivative at t={t_:.9g} ({_state_text(sw.model, z)})", t=float(t_))
        return d

    return f


def _collect_events(res, K, user_events, t_events, y_events):
    """Record the user events of a segment; return ((k, t, z) of the switch event that ended it or None,
    whether a terminal user event stopped the run)."""
    fired, user_stop = None, False
    for j, tev in enumerate(res.t_events or []):
        if not len(tev):
            continue
        if j >= K:
            t_events[j - K].extend(tev)
            y_events[j - K].extend(res.y_events[j])
            user_stop = user_stop or bool(getattr(user_events[j - K], "terminal", False))
        elif fired is None:
            fired = (j, float(tev[-1]), np.array(res.y_events[j][-1], dtype=float))
    return fired, user_stop


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
    transitions: tuple = ()

    def __post_init__(self):
        self.t_events = [np.array(v) for v in self.t_events]
        self.y_events = [np.array(v) for v in self.y_events]
