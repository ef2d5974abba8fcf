r"""Constraint blocks for the multiplier form of Lagrange's equations (Wells ch. 12, superfluous coordinates).

With velocity-level constraints ``g = A(q, t) q̇ + b(q, t) = 0`` the equations become

.. math::

    M\ddot q = f + A^{\mathsf T}\lambda, \qquad A\ddot q = c,
    \qquad c = -\Big(\sum_j \frac{\partial g}{\partial q_j}\dot q_j + \frac{\partial g}{\partial t}\Big)
    \Big|_{\ddot q\text{-free}},

an index-1 system for (q̈, λ). ``λ_k A_kr`` is the generalized force of constraint on coordinate r —
Wells' 𝓕_qr of eq. (12.3): the reaction "distorted" by +δq_r with t frozen.
"""

from __future__ import annotations

import sympy as sp

from .. import limits
from ..conventions import t
from ..model.coordinates import to_symbols
from ..symengine_bridge import jacobian

__all__ = ["constraint_blocks", "multiplier_symbols", "PLANAR_STOP_SPEED"]

#: Friction over a surface (``Rough`` with sliding components): the sliding function whose zero ends a run with
#: exact friction is ``|v| − PLANAR_STOP_SPEED`` (|v| only touches 0, it does not change sign).
PLANAR_STOP_SPEED = sp.Float(1e-9)


def multiplier_symbols(m: int) -> tuple:
    """``lambda_1 … lambda_m`` (real symbols)."""
    return tuple(sp.Symbol(f"lambda_{k + 1}", real=True) for k in range(m))


def constraint_blocks(specs, coords, q, qd) -> dict:
    """A, b, c and φ in plain symbols for the validated constraints ``specs``."""
    n, m = len(q), len(specs)
    A = sp.zeros(m, n)
    b, c, phi = [], [], []
    gs = [to_symbols(spec.velocity, coords) for spec in specs]
    # ∂g/∂q̇ (the rows of A), ∂g/∂q and ∂g/∂t: by symengine for large constraints (a bicycle's rolling wheels)
    variables = [*qd, *q, t]
    fast = jacobian(gs, variables)
    for k, spec in enumerate(specs):
        g = gs[k]
        d = fast[k] if fast is not None else [sp.diff(g, v) for v in variables]
        for j in range(n):
            A[k, j] = d[j]
        bk = g - sp.Add(*(A[k, j] * qd[j] for j in range(n)))
        limits.checkpoint()
        bk = sp.expand(bk)  # under the stage's deadline, counted once built (lagrange.limits)
        limits.measure(bk, what=f"the velocity-free part of constraint {spec.name}")
        b.append(bk)
        # d/dt g = A q̈ + (∂g/∂q) q̇ + ∂g/∂t ; with g linear in q̇, ∂g/∂q contains q̇ (that is Ȧ q̇ + ḃ)
        rate = sum((d[n + j] * qd[j] for j in range(n)), sp.S.Zero) + d[2 * n]
        c.append(-rate)
        phi.append(None if spec.position is None else to_symbols(spec.position, coords))
    lam = multiplier_symbols(m)
    B = sp.Matrix(A.T)  # reaction matrix: M q̈ = f + B λ
    signs, sliding, planar = [], [], []
    for k, spec in enumerate(specs):
        if spec.friction is None:
            continue
        mu, vs, normal = spec.friction
        sigma = sp.Symbol(f"_rough{k}", real=True)  # sign(λ_k)·sign(v_s), fixed within a segment
        signs.append(sigma)
        if isinstance(vs, tuple):  # over a surface: −μ N Σ_i (v_i/|v|) ∂v_i/∂q̇ with σ = sign(λ_k)
            comps = [to_symbols(v, coords) for v in vs]
            speed2 = sp.Add(*[v**2 for v in comps])
            inv = sp.Pow(speed2, sp.Rational(-1, 2))  # regularized by lagrange.codegen.rough_friction
            sliding.append((k, sp.sqrt(speed2) - PLANAR_STOP_SPEED))
            planar.append((k, speed2))
            for j in range(n):
                B[j, k] -= mu * to_symbols(normal, coords) * sigma * inv * sp.Add(
                    *[v * sp.diff(v, qd[j]) for v in comps])
            continue
        vs_s = to_symbols(vs, coords)
        sliding.append((k, vs_s))
        for j in range(n):
            B[j, k] -= mu * to_symbols(normal, coords) * sigma * sp.diff(vs_s, qd[j])
    return {
        "reaction_matrix": sp.ImmutableMatrix(B),
        "rough_signs": tuple(signs),
        "sliding_velocities": tuple(sliding),
        "planar_friction": tuple(planar),
        "constraint_names": tuple(s.name for s in specs),
        "constraint_matrix": sp.ImmutableMatrix(A),
        "constraint_bias": tuple(b),
        "constraint_rhs": tuple(c),
        "constraint_positions": tuple(phi),
        "multipliers": lam,
        "unilateral": tuple(s.unilateral for s in specs),
    }
