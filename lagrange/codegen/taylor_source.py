r"""A model's Taylor-series function as straight-line numba source: the compiled fast path of
``method="taylor"`` (``backend="numba"``).

The tape (:mod:`lagrange.codegen.tape`) is written out instruction by instruction with literal slot
numbers, the recurrences of :mod:`lagrange.integrate._taylor_loop` inlined (same arithmetic in the same
order, so the results equal the interpreter's), constant mass-matrix entries dropped from the order-k
sums (their higher coefficients are zero)::

    series(t, S, acc, L, d, Mk, r, p_order) -> ok

fills ``S[:, 0..p_order]`` from the state ``S[:nz, 0]`` (False when the mass matrix is not positive
definite). It is compiled eagerly with the signature :data:`SERIES_SIGNATURE` and handed to the generic
driver ``taylor_fn`` of the kernel as a numba first-class function, like ``field`` for the DOP853 loop.
"""

from __future__ import annotations

from .tape import OPCODES, Tape

__all__ = ["series_source", "SERIES_SIGNATURE"]

SERIES_SIGNATURE = ("boolean(float64, float64[:, ::1], float64[:, ::1], float64[:, ::1], float64[::1], "
                    "float64[:, ::1], float64[::1], int64)")
_INV = {v: k for k, v in OPCODES.items()}


def _instruction(op: str, a: int, b: int, o: int, c: float) -> list[str]:
    """Lines computing ``S[o, k]`` (and ``S[b, k]`` for SINCOS) — the recurrences of ``_coefficient``."""
    conv = {
        "MUL": ["s = 0.0", "for j in range(k + 1):", f"    s += S[{a}, j] * S[{b}, k - j]", f"S[{o}, k] = s"],
        "ADD": [f"S[{o}, k] = S[{a}, k] + S[{b}, k]"],
        "MULC": [f"S[{o}, k] = S[{a}, k] * S[{b}, 0]"],
        "SUB": [f"S[{o}, k] = S[{a}, k] - S[{b}, k]"],
        "ADDC": [f"S[{o}, k] = S[{a}, k] + S[{b}, 0] if k == 0 else S[{a}, k]"],
        "SUBVC": [f"S[{o}, k] = S[{a}, k] - S[{b}, 0] if k == 0 else S[{a}, k]"],
        "SUBCV": [f"S[{o}, k] = S[{a}, 0] - S[{b}, 0] if k == 0 else -S[{b}, k]"],
        "NEG": [f"S[{o}, k] = -S[{a}, k]"],
        "DIVVC": [f"S[{o}, k] = S[{a}, k] / S[{b}, 0]"],
        "DIV": [f"s = S[{a}, k]", "for j in range(1, k + 1):", f"    s -= S[{b}, j] * S[{o}, k - j]",
                f"S[{o}, k] = s / S[{b}, 0]"],
        "DIVCV": [f"s = S[{a}, k] if k == 0 else 0.0", "for j in range(1, k + 1):",
                  f"    s -= S[{b}, j] * S[{o}, k - j]", f"S[{o}, k] = s / S[{b}, 0]"],
        "SINCOS": ["if k == 0:", f"    S[{o}, 0] = math.sin(S[{a}, 0])", f"    S[{b}, 0] = math.cos(S[{a}, 0])",
                   "else:", "    s = 0.0", "    cc = 0.0", "    for j in range(1, k + 1):",
                   f"        s += j * S[{a}, j] * S[{b}, k - j]", f"        cc += j * S[{a}, j] * S[{o}, k - j]",
                   f"    S[{o}, k] = s / k", f"    S[{b}, k] = -cc / k"],
        "EXP": ["if k == 0:", f"    S[{o}, 0] = math.exp(S[{a}, 0])", "else:", "    s = 0.0",
                "    for j in range(1, k + 1):", f"        s += j * S[{a}, j] * S[{o}, k - j]",
                f"    S[{o}, k] = s / k"],
        "LOG": ["if k == 0:", f"    S[{o}, 0] = math.log(S[{a}, 0]) if S[{a}, 0] > 0.0 else math.nan", "else:",
                "    s = 0.0", "    for j in range(1, k):", f"        s += j * S[{o}, j] * S[{a}, k - j]",
                f"    S[{o}, k] = (S[{a}, k] - s / k) / S[{a}, 0]"],
        "POW": ["if k == 0:", f"    S[{o}, 0] = S[{a}, 0] ** {c!r}", "else:", "    s = 0.0", "    for j in range(k):",
                f"        s += ({c!r} * (k - j) - j) * S[{a}, k - j] * S[{o}, j]",
                f"    S[{o}, k] = s / (k * S[{a}, 0])"],
    }
    return conv[op]


def _solve_lines(tape: Tape, variable: set) -> list[str]:
    """LDLᵀ of M_0 at order 0, then ``M_0 a_k = f_k − Σ_{j≥1} M_j a_{k−j}`` (variable entries of M only)."""
    n = tape.n
    lines = ["if k == 0:"]
    for i in range(n):
        for j in range(n):
            s = int(tape.mass[min(i, j), max(i, j)])
            lines.append(f"    Mk[{i}, {j}] = {f'S[{s}, 0]' if s >= 0 else '0.0'}")
    lines += [f"    for jj in range({n}):", "        dj = Mk[jj, jj]", "        for kk in range(jj):",
              "            dj -= L[jj, kk] * L[jj, kk] * d[kk]", "        if not (dj > 1e-13 * abs(Mk[jj, jj])):",
              "            return False", "        d[jj] = dj", "        L[jj, jj] = 1.0",
              f"        for ii in range(jj + 1, {n}):", "            s = Mk[ii, jj]",
              "            for kk in range(jj):",
              "                s -= L[ii, kk] * L[jj, kk] * d[kk]", "            L[ii, jj] = s / dj"]
    for i in range(n):
        lines.append(f"s = S[{int(tape.force[i])}, k]")
        for l_ in range(n):
            m = int(tape.mass[min(i, l_), max(i, l_)])
            if m >= 0 and m in variable:
                lines += ["for j in range(1, k + 1):", f"    s -= S[{m}, j] * acc[{l_}, k - j]"]
        lines.append(f"r[{i}] = s")
    lines += [f"for i in range({n}):", "    s = r[i]", "    for j in range(i):", "        s -= L[i, j] * r[j]",
              "    r[i] = s", f"for i in range({n - 1}, -1, -1):", "    s = r[i] / d[i]",
              f"    for j in range(i + 1, {n}):", "        s -= L[j, i] * acc[j, k]", "    acc[i, k] = s",
              f"for i in range({n}):", "    S[i, k + 1] = S[" + str(n) + " + i, k] / (k + 1)",
              f"    S[{n} + i, k + 1] = acc[i, k] / (k + 1)"]
    if tape.power >= 0:
        lines.append(f"S[{2 * n}, k + 1] = S[{tape.power}, k] / (k + 1)")
    return lines


def series_source(tape: Tape) -> str:
    """Module text defining the eagerly compiled ``series`` of ``tape`` (see the module docstring)."""
    variable = set(range(tape.nz + 1)) | {int(row[3]) for row in tape.code}
    variable |= {int(row[2]) for row in tape.code if _INV[int(row[0])] == "SINCOS"}
    body = [f"S[{tape.slot_t}, 0] = t", f"S[{tape.slot_t}, 1] = 1.0", "for k in range(p_order):"]
    for (op, a, b, o), c in zip(tape.code.tolist(), tape.consts.tolist()):
        body += ["    " + line for line in _instruction(_INV[op], a, b, o, c)]
    body += ["    " + line for line in _solve_lines(tape, variable)]
    body.append("return True")
    return ("import math\n\nimport numba\n\n\n"
            f"@numba.njit({SERIES_SIGNATURE!r}, cache=True, error_model='numpy')\n"
            "def series(t, S, acc, L, d, Mk, r, p_order):\n" + "\n".join("    " + line for line in body) + "\n")
