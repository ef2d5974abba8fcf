r"""The driver of the compiled Taylor series (numba): step rule, dense output and bookkeeping around a model's
``series`` (:mod:`lagrange.codegen.taylor_source`). The tape's interpreter is the C one
(:file:`_taylor_interp.c`, which has the same arithmetic); the numba interpreter that used to live here was
retired (docs/guide.md, "The Taylor method: what is kept and why").

A model's right-hand side comes as a *tape* (:mod:`lagrange.codegen.tape`): a straight-line list of
elementary operations on numbered slots. Each slot holds a truncated Taylor series in time,
``S[slot, k]`` = the k-th normalized derivative ``x^{[k]} = x^{(k)}(t)/k!``. Evaluating the tape at order
``k`` computes coefficient ``k`` of every slot from the coefficients ``0..k`` of its operands by the
classic recurrences of automatic differentiation (Moore; Jorba & Zou, *Experimental Mathematics* 14 (2005)
99–117; Hairer, Nørsett & Wanner, *Solving ODEs I*, §I.8)::

    c = a·b      c_k = Σ_{j=0..k} a_j b_{k−j}
    c = a/b      c_k = (a_k − Σ_{j=1..k} b_j c_{k−j}) / b_0
    e = exp(u)   e_k = (1/k) Σ_{j=1..k} j u_j e_{k−j}
    l = log(u)   l_k = (u_k − (1/k) Σ_{j=1..k−1} j l_j u_{k−j}) / u_0
    s = sin(u), c = cos(u)
                 s_k = (1/k) Σ_{j=1..k} j u_j c_{k−j},   c_k = −(1/k) Σ_{j=1..k} j u_j s_{k−j}
    w = u^α      w_k = (1/(k u_0)) Σ_{j=0..k−1} (α(k−j) − j) u_{k−j} w_j

The state is ``z = [q, v(, work)]`` with ``q' = v``, ``M(q, v, t) v' = f(q, v, t)`` and ``work' = P``. The
linear solve is done order by order: with ``a = v'``, ``M a = f`` gives

    M_0 a_k = f_k − Σ_{j=1..k} M_j a_{k−j},

one LDLᵀ factorization of ``M_0`` per step and one solve per order; then ``q_{k+1} = v_k/(k+1)``,
``v_{k+1} = a_k/(k+1)``, ``work_{k+1} = P_k/(k+1)``.

Every division is written as a product with a reciprocal, ``x · (1/y)``: the reciprocals (of ``k``, of
``u_0``, of the pivots) do not depend on the order-k sums, so in the compiled series they leave the chain of
dependent operations that runs from one order to the next (a division's latency is several times a
product's); the interpreter does the same arithmetic, so all three forms give equal results.

Order and step (Jorba & Zou 2005, as in heyoka): with tolerance ε the order is
``p = ceil(−ln(ε)/2 + 1)``, and the step is ``h = ρ/e² · exp(−0.7/(p−1))`` with
``ρ = min_{k ∈ {p−1, p}} (N/‖z^{[k]}‖∞)^{1/k}`` and ``N = max(A, ‖z^{[0]}‖∞)``: an absolute criterion for
small states and a relative one for large states (``A = atol/rtol``; A = 1 is Jorba & Zou's mixed
criterion). There are no rejected steps. The output at ``t_eval`` is the Taylor polynomial of the step
that contains it (the dense output is exact to the order of the method), so steps are never clipped to
output times.

The entry point :func:`taylor_fn` is compiled on request through :func:`entry`; :func:`_coefficient` (the
recurrences) runs the tape's constant instructions at order 0.

The tape's instructions are rows ``(op, a, b, out)`` of an int64 array with one float64 constant each;
*constant* instructions (parameters, numbers and what depends on them only) run once per integration at
order 0, and their higher coefficients stay zero; the others run at every order of every step.

This file must stay self-contained (absolute imports of numpy and numba only): it is imported as a copy in
the cache directory (like :mod:`lagrange.integrate._rk_loops`).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.core.types import FunctionType

# opcodes (lagrange.codegen.tape uses the same numbers)
LOADC, LOADP, ADD, ADDC, SUB, SUBVC, SUBCV, MUL, MULC, DIV, DIVVC, DIVCV, NEG, SINCOS, EXP, LOG, POW = range(17)

_I2 = types.int64[:, ::1]
_F1 = types.float64[::1]
#: ``(status, t reached, z reached, Y, n_out, steps)``
RESULT = types.Tuple((types.int64, types.float64, _F1, types.float64[:, ::1], types.int64, types.int64))
_F2 = types.float64[:, ::1]
#: a model's compiled ``series(t, S, acc, L, d, Mk, r, p_order) -> ok`` (lagrange.codegen.taylor_source)
SERIES = types.boolean(types.float64, _F2, _F2, _F2, _F1, _F2, _F1, types.int64)
TAYLOR_FN = RESULT(FunctionType(SERIES), _I2, _F1, types.int64, types.int64, types.int64, types.float64,
                               types.float64, _F1, _F1, types.float64, types.int64, types.float64, _F1, types.int64)


@njit(cache=True, error_model="numpy", inline="always")
def _pow0(x: float, c: float) -> float:
    """``x**c`` at order 0: the half-integer powers (gravitation's r^−3/2, a pendulum's length) by a square
    root, a third of ``pow``'s cost; :func:`lagrange.codegen.taylor_source.pow0_text` writes the same."""
    if c == -1.5:
        return 1.0 / (x * math.sqrt(x))
    if c == -0.5:
        return 1.0 / math.sqrt(x)
    if c == 0.5:
        return math.sqrt(x)
    if c == 1.5:
        return x * math.sqrt(x)
    return x ** c


@njit(cache=True, error_model="numpy", inline="always")
def _coefficient(op: int, a: int, b: int, o: int, c: float, S, k: int) -> None:
    """Coefficient ``k`` of slot ``o`` (see the module docstring); ``S[:, :k]`` is known."""
    if op == MUL:
        s = 0.0
        for j in range(k + 1):
            s += S[a, j] * S[b, k - j]
        S[o, k] = s
    elif op == ADD:
        S[o, k] = S[a, k] + S[b, k]
    elif op == MULC:
        S[o, k] = S[a, k] * S[b, 0]
    elif op == SUB:
        S[o, k] = S[a, k] - S[b, k]
    elif op == ADDC:
        S[o, k] = S[a, k] + S[b, 0] if k == 0 else S[a, k]
    elif op == SUBVC:
        S[o, k] = S[a, k] - S[b, 0] if k == 0 else S[a, k]
    elif op == SUBCV:
        S[o, k] = S[a, 0] - S[b, 0] if k == 0 else -S[b, k]
    elif op == NEG:
        S[o, k] = -S[a, k]
    elif op == DIVVC:
        S[o, k] = S[a, k] * (1.0 / S[b, 0])
    elif op == DIV or op == DIVCV:
        s = S[a, k] if (op == DIV or k == 0) else 0.0
        for j in range(1, k + 1):
            s -= S[b, j] * S[o, k - j]
        S[o, k] = s * (1.0 / S[b, 0])
    elif op == SINCOS:  # o = sin(a), b = cos(a)
        if k == 0:
            S[o, 0] = math.sin(S[a, 0])
            S[b, 0] = math.cos(S[a, 0])
        else:
            s = 0.0
            cc = 0.0
            for j in range(1, k + 1):
                s += j * S[a, j] * S[b, k - j]
                cc += j * S[a, j] * S[o, k - j]
            S[o, k] = s * (1.0 / k)
            S[b, k] = -cc * (1.0 / k)
    elif op == EXP:
        if k == 0:
            S[o, 0] = math.exp(S[a, 0])
        else:
            s = 0.0
            for j in range(1, k + 1):
                s += j * S[a, j] * S[o, k - j]
            S[o, k] = s * (1.0 / k)
    elif op == LOG:
        if k == 0:
            S[o, 0] = math.log(S[a, 0]) if S[a, 0] > 0.0 else math.nan
        else:
            s = 0.0
            for j in range(1, k):
                s += j * S[o, j] * S[a, k - j]
            S[o, k] = (S[a, k] - s * (1.0 / k)) * (1.0 / S[a, 0])
    elif op == POW:
        if k == 0:
            S[o, 0] = _pow0(S[a, 0], c)
        else:
            s = 0.0
            for j in range(k):
                s += (c * (k - j) - j) * S[a, k - j] * S[o, j]
            S[o, k] = s * (1.0 / (k * S[a, 0]))
    elif op == LOADC:
        S[o, 0] = c


@njit(cache=True, error_model="numpy")
def _horner(S, nz: int, p_order: int, x: float, out) -> None:
    for i in range(nz):
        v = S[i, p_order]
        for k in range(p_order - 1, -1, -1):
            v = v * x + S[i, k]
        out[i] = v


@njit(cache=True, error_model="numpy")
def _step_rule(p_order: int):
    """The constants of Jorba & Zou's step for order p: ``(1/(p−1), 1/p, exp(−0.7/(p−1))/e²)``, once per run."""
    return 1.0 / (p_order - 1), 1.0 / p_order, math.exp(-0.7 / (p_order - 1)) / (math.e * math.e)


@njit(cache=True, error_model="numpy", inline="always")
def _step_size(S, nz: int, p_order: int, floor: float, rule) -> float:
    """Jorba & Zou's step: ρ/e² · exp(−0.7/(p−1)), ρ from the last two orders (module docstring; ``rule`` from
    :func:`_step_rule`); NaN when a coefficient of order 0, p − 1 or p is not finite."""
    n0 = 0.0
    n1 = 0.0
    n2 = 0.0
    bad = 0.0  # stays 0 unless a coefficient of the last two orders or of order 0 is inf or NaN
    for i in range(nz):
        n0 = max(n0, abs(S[i, 0]))
        n1 = max(n1, abs(S[i, p_order - 1]))
        n2 = max(n2, abs(S[i, p_order]))
        bad += 0.0 * (S[i, 0] + S[i, p_order - 1] + S[i, p_order])
    if bad != 0.0:
        return math.nan
    scale = max(floor, n0)
    rho = math.inf
    if n1 > 0.0:
        rho = (scale / n1) ** rule[0]
    if n2 > 0.0:
        rho = min(rho, (scale / n2) ** rule[1])
    return rho * rule[2]


@njit(cache=True, error_model="numpy")
def _constants(const_code, const_vals, n_slots, n, p_order, p):
    """The work arrays ``(S, acc, L, d, Mk, r)`` with the constant instructions evaluated into ``S[:, 0]``."""
    S = np.zeros((n_slots, p_order + 1))
    for i in range(const_code.shape[0]):
        if const_code[i, 0] == LOADP:
            S[const_code[i, 3], 0] = p[const_code[i, 1]]
        else:
            _coefficient(const_code[i, 0], const_code[i, 1], const_code[i, 2], const_code[i, 3], const_vals[i],
                         S, 0)
    return S, np.zeros((n, p_order + 1)), np.zeros((n, n)), np.zeros(n), np.zeros((n, n)), np.zeros(n)


@njit(cache=True, error_model="numpy", inline="always")
def _advance(S, nz, p_order, floor, rule, max_step, t, t1, direction, t_eval, n_out, Y, z):
    """After the series at ``t``: check it, take Jorba & Zou's step (writing outputs at ``t_eval`` in it and the
    new state into ``z``); ``(status, t_new, n_out)``."""
    h_abs = _step_size(S, nz, p_order, floor, rule)
    if h_abs != h_abs:  # a NaN norm: non-finite coefficients
        return 2, t, n_out
    h_abs = min(h_abs, max_step)
    if not (h_abs >= 10.0 * abs(np.nextafter(t, direction * np.inf) - t)):
        return 1, t, n_out
    t_new = t + direction * h_abs
    if direction * (t_new - t1) >= 0.0:
        t_new = t1
    # the new state sums every coefficient: finite exactly when they all are (checked before any output)
    _horner(S, nz, p_order, t_new - t, z)
    for i in range(nz):
        if not math.isfinite(z[i]):
            _horner(S, nz, 0, 0.0, z)  # back to the state at t
            return 2, t, n_out
    while n_out < t_eval.size and direction * (t_eval[n_out] - t_new) <= 0.0:
        _horner(S, nz, p_order, t_eval[n_out] - t, Y[n_out])
        n_out += 1
    return 0, t_new, n_out


def taylor_fn(series, const_code, const_vals, n_slots, n, nz, t0, t1, z0, p, floor, p_order, max_step, t_eval,
              max_steps):
    """Integrate from ``(t0, z0)`` to ``t1`` with the model's compiled ``series``
    (:mod:`lagrange.codegen.taylor_source`); outputs at ``t_eval`` (sorted in the direction of integration).

    ``const_code``/``const_vals``: the tape's instructions run once at order 0 (``LOADP`` reads ``p[a]``);
    slots ``0..nz−1`` are the state. ``floor`` and ``p_order``: A and p of the module docstring. At most
    ``max_steps`` steps (status 4 then: the caller resumes from the returned time and state, bit for bit as an
    uninterrupted run). Status codes as :class:`lagrange.integrate.compiled.LoopStatus`."""
    S, acc, L, d, Mk, r = _constants(const_code, const_vals, n_slots, n, p_order, p)
    rule = _step_rule(p_order)
    z = z0.copy()
    Y = np.empty((t_eval.size, nz))
    direction = 1.0 if t1 >= t0 else -1.0
    t, n_out, steps = t0, 0, 0
    while direction * (t - t1) < 0.0:
        if steps >= max_steps:
            return 4, t, z, Y, n_out, steps
        S[:nz, 0] = z
        if not series(t, S, acc, L, d, Mk, r, p_order):
            return 3, t, z, Y, n_out, steps
        status, t, n_out = _advance(S, nz, p_order, floor, rule, max_step, t, t1, direction, t_eval, n_out, Y, z)
        if status != 0:
            return status, t, z, Y, n_out, steps
        steps += 1
    return 0, t, z, Y, n_out, steps


_SIGNATURES = {"taylor_fn": TAYLOR_FN}
_ENTRIES: dict = {}


def entry(name: str):
    """The compiled entry point ``name`` (``"taylor_fn"``), compiled for its signature — or
    loaded from numba's cache — on first request: loading a cached entry costs about 0.2 s, so a process pays
    only for the entry it uses."""
    if name not in _ENTRIES:
        _ENTRIES[name] = njit(_SIGNATURES[name], cache=True, error_model="numpy")(globals()[name])
    return _ENTRIES[name]
