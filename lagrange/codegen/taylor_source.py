r"""A model's Taylor-series function as straight-line numba source: the compiled fast path of
``method="taylor"`` (``backend="numba"``).

The tape (:mod:`lagrange.codegen.tape`) is written out instruction by instruction with literal slot
numbers, the recurrences of the C interpreter (:file:`lagrange/integrate/_taylor_interp.c`) inlined (same
arithmetic in the same order), constant mass-matrix entries dropped from the order-k
sums (their higher coefficients are zero)::

    series(t, S, acc, L, d, Mk, r, p_order) -> ok

fills ``S[:, 0..p_order]`` from the state ``S[:nz, 0]`` (False when the mass matrix is not positive
definite). It is compiled eagerly with the signature :data:`SERIES_SIGNATURE` and handed to the generic
driver ``taylor_fn`` of the kernel as a numba first-class function, like ``field`` for the DOP853 loop.

Two forms, same arithmetic:

* :func:`series_source` — loops over the order ``k`` and over each recurrence's sum (any order);
* :func:`unrolled_source` — specialized to one order ``p``: every sum written out term by term in scalar
  locals (terms with a structurally zero factor — the higher coefficients of constants and of ``t`` —
  left out), as heyoka's non-compact mode does. No loop control, no branches, everything in registers:
  measured 1.3–1.6× faster per step than the loop form (Kepler, double pendulum, top at order 11), at the
  cost of one JIT compile per (model, order), cached on disk. Used when the written-out sums stay below
  :data:`UNROLL_TERMS` terms (small systems, moderate orders); otherwise the loop form.

Both evaluate each recurrence's terms in the same order as the interpreter, so results are equal (up to
the sign of an exact zero).
"""

from __future__ import annotations

import weakref

from .tape import OPCODES, Tape

__all__ = ["series_source", "unrolled_source", "unrolled_terms", "compiled_series", "SERIES_SIGNATURE",
           "UNROLL_TERMS"]

SERIES_SIGNATURE = ("boolean(float64, float64[:, ::1], float64[:, ::1], float64[:, ::1], float64[::1], "
                    "float64[:, ::1], float64[::1], int64)")
_INV = {v: k for k, v in OPCODES.items()}
#: largest number of written-out terms for :func:`unrolled_source`: JIT compilation takes about 1.7 ms per
#: term (measured: heavy top at order 11, 1,254 terms, 2.0 s; double pendulum at order 20, 2,560 terms,
#: 4.9 s), so this caps it near 3.5 s; larger tapes or orders get the loop form (about 1 s)
UNROLL_TERMS = 2000


def pow0_text(x: str, c: float) -> str:
    """Source of ``x**c`` at order 0, as the interpreter computes it (``_taylor_loop._pow0``): the
    half-integer powers by a square root, the rest by ``**``."""
    special = {-1.5: f"1.0 / ({x} * math.sqrt({x}))", -0.5: f"1.0 / math.sqrt({x})", 0.5: f"math.sqrt({x})",
               1.5: f"{x} * math.sqrt({x})"}
    return special.get(c, f"{x} ** {c!r}")


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
        "DIVVC": [f"S[{o}, k] = S[{a}, k] * (1.0 / S[{b}, 0])"],
        "DIV": [f"s = S[{a}, k]", "for j in range(1, k + 1):", f"    s -= S[{b}, j] * S[{o}, k - j]",
                f"S[{o}, k] = s * (1.0 / S[{b}, 0])"],
        "DIVCV": [f"s = S[{a}, k] if k == 0 else 0.0", "for j in range(1, k + 1):",
                  f"    s -= S[{b}, j] * S[{o}, k - j]", f"S[{o}, k] = s * (1.0 / S[{b}, 0])"],
        "SINCOS": ["if k == 0:", f"    S[{o}, 0] = math.sin(S[{a}, 0])", f"    S[{b}, 0] = math.cos(S[{a}, 0])",
                   "else:", "    s = 0.0", "    cc = 0.0", "    for j in range(1, k + 1):",
                   f"        s += j * S[{a}, j] * S[{b}, k - j]", f"        cc += j * S[{a}, j] * S[{o}, k - j]",
                   f"    S[{o}, k] = s * (1.0 / k)", f"    S[{b}, k] = -cc * (1.0 / k)"],
        "EXP": ["if k == 0:", f"    S[{o}, 0] = math.exp(S[{a}, 0])", "else:", "    s = 0.0",
                "    for j in range(1, k + 1):", f"        s += j * S[{a}, j] * S[{o}, k - j]",
                f"    S[{o}, k] = s * (1.0 / k)"],
        "LOG": ["if k == 0:", f"    S[{o}, 0] = math.log(S[{a}, 0]) if S[{a}, 0] > 0.0 else math.nan", "else:",
                "    s = 0.0", "    for j in range(1, k):", f"        s += j * S[{o}, j] * S[{a}, k - j]",
                f"    S[{o}, k] = (S[{a}, k] - s * (1.0 / k)) * (1.0 / S[{a}, 0])"],
        "POW": ["if k == 0:", f"    S[{o}, 0] = {pow0_text(f'S[{a}, 0]', c)}", "else:", "    s = 0.0",
                "    for j in range(k):",
                f"        s += ({c!r} * (k - j) - j) * S[{a}, k - j] * S[{o}, j]",
                f"    S[{o}, k] = s * (1.0 / (k * S[{a}, 0]))"],
    }
    return conv[op]


def _solve_lines(tape: Tape, variable: set) -> list[str]:
    """LDLᵀ of M_0 at order 0, then ``M_0 a_k = f_k − Σ_{j≥1} M_j a_{k−j}`` (variable entries of M only)."""
    n = tape.n
    lines = ["if k == 0:"] + ["    " + line for line in _ldl_lines(tape, lambda s: f"S[{s}, 0]")]
    for i in range(n):
        lines.append(f"s = S[{int(tape.force[i])}, k]")
        for l_ in range(n):
            m = int(tape.mass[min(i, l_), max(i, l_)])
            if m >= 0 and m in variable:
                lines += ["for j in range(1, k + 1):", f"    s -= S[{m}, j] * acc[{l_}, k - j]"]
        lines.append(f"r[{i}] = s")
    lines += [f"for i in range({n}):", "    s = r[i]", "    for j in range(i):", "        s -= L[i, j] * r[j]",
              "    r[i] = s", f"for i in range({n - 1}, -1, -1):", "    s = r[i] * (1.0 / d[i])",
              f"    for j in range(i + 1, {n}):", "        s -= L[j, i] * acc[j, k]", "    acc[i, k] = s",
              f"for i in range({n}):", "    S[i, k + 1] = S[" + str(n) + " + i, k] * (1.0 / (k + 1))",
              f"    S[{n} + i, k + 1] = acc[i, k] * (1.0 / (k + 1))"]
    if tape.power >= 0:
        lines.append(f"S[{2 * n}, k + 1] = S[{tape.power}, k] * (1.0 / (k + 1))")
    return lines


def _ldl_lines(tape: Tape, entry) -> list[str]:
    """``Mk`` = M_0 (``entry(slot)``: the text of a slot's order-0 value) factorized into unit-lower ``L`` and
    ``d``; ``return False`` when a pivot is not positive relative to its diagonal entry (1e-13), as the
    interpreter's ``_ldl`` does."""
    n = tape.n
    lines = []
    for i in range(n):
        for j in range(n):
            s = int(tape.mass[min(i, j), max(i, j)])
            lines.append(f"Mk[{i}, {j}] = {entry(s) if s >= 0 else '0.0'}")
    return lines + [f"for jj in range({n}):", "    dj = Mk[jj, jj]", "    for kk in range(jj):",
                    "        dj -= L[jj, kk] * L[jj, kk] * d[kk]", "    if not (dj > 1e-13 * abs(Mk[jj, jj])):",
                    "        return False", "    d[jj] = dj", "    L[jj, jj] = 1.0",
                    f"    for ii in range(jj + 1, {n}):", "        s = Mk[ii, jj]", "        for kk in range(jj):",
                    "            s -= L[ii, kk] * L[jj, kk] * d[kk]", "        L[ii, jj] = s / dj"]


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


def _variable_slots(tape: Tape) -> set:
    variable = set(range(tape.nz)) | {int(row[3]) for row in tape.code}
    return variable | {int(row[2]) for row in tape.code if _INV[int(row[0])] == "SINCOS"}


def unrolled_terms(tape: Tape, order: int) -> int:
    """Number of product terms :func:`unrolled_source` would write (its size, which sets the JIT time)."""
    per_order = {"MUL": lambda k: k + 1, "DIV": lambda k: k, "DIVCV": lambda k: k, "SINCOS": lambda k: 2 * k,
                 "EXP": lambda k: k, "LOG": lambda k: max(k - 1, 0), "POW": lambda k: k}
    total = 0
    for row in tape.code.tolist():
        f = per_order.get(_INV[row[0]])
        total += sum(f(k) for k in range(order)) if f else order
    variable = _variable_slots(tape)
    m_var = sum(1 for i in range(tape.n) for j in range(tape.n) if int(tape.mass[min(i, j), max(i, j)]) in variable)
    return total + m_var * order * (order - 1) // 2 + tape.n * tape.n * order


def unrolled_source(tape: Tape, order: int) -> str:
    """Module text defining ``series`` for the fixed order ``order`` (``p_order`` must equal it), every sum
    written out (see the module docstring)."""
    nz, slot_t = tape.nz, tape.slot_t
    variable = _variable_slots(tape)
    constants: set = set()

    def v(slot: int, k: int) -> str:
        if slot == slot_t:
            return "t" if k == 0 else ("1.0" if k == 1 else "0.0")
        if slot in variable:
            return f"v{slot}_{k}"
        if k:
            return "0.0"
        constants.add(slot)
        return f"c{slot}"

    def total(terms: list[str], first: str = "") -> str:
        """``first`` then ``+ term`` for each term, left to right, products with a 0.0 factor left out."""
        kept = [x for x in terms if "0.0" not in x.split(" * ")]
        if not first:
            return " + ".join(kept) if kept else "0.0"
        return first + "".join(f" - {x}" for x in kept)

    lines = [f"v{i}_0 = S[{i}, 0]" for i in range(nz)]
    for k in range(order):
        for (op, a, b, o), c in zip(tape.code.tolist(), tape.consts.tolist()):
            name = _INV[op]
            if name == "SINCOS":
                if k == 0:
                    lines += [f"{v(o, 0)} = math.sin({v(a, 0)})", f"{v(b, 0)} = math.cos({v(a, 0)})"]
                else:
                    sj = total([f"{j}.0 * {v(a, j)} * {v(b, k - j)}" for j in range(1, k + 1)])
                    cj = total([f"{j}.0 * {v(a, j)} * {v(o, k - j)}" for j in range(1, k + 1)])
                    lines += [f"{v(o, k)} = ({sj}) * {1 / k!r}", f"{v(b, k)} = -({cj}) * {1 / k!r}"]
                continue
            if name == "MUL":
                e = total([f"{v(a, j)} * {v(b, k - j)}" for j in range(k + 1)])
            elif name in ("ADD", "SUB"):
                e = f"{v(a, k)} {'+' if name == 'ADD' else '-'} {v(b, k)}"
            elif name == "MULC":
                e = f"{v(a, k)} * {v(b, 0)}"
            elif name in ("ADDC", "SUBVC"):
                e = f"{v(a, 0)} {'+' if name == 'ADDC' else '-'} {v(b, 0)}" if k == 0 else v(a, k)
            elif name == "SUBCV":
                e = f"{v(a, 0)} - {v(b, 0)}" if k == 0 else f"-{v(b, k)}"
            elif name == "NEG":
                e = f"-{v(a, k)}"
            elif name == "DIVVC":
                e = f"{v(a, k)} * (1.0 / {v(b, 0)})"
            elif name in ("DIV", "DIVCV"):
                first = v(a, k) if (name == "DIV" or k == 0) else "0.0"
                e = f"({total([f'{v(b, j)} * {v(o, k - j)}' for j in range(1, k + 1)], first)}) * (1.0 / {v(b, 0)})"
            elif name == "EXP":
                e = (f"math.exp({v(a, 0)})" if k == 0 else
                     f"({total([f'{j}.0 * {v(a, j)} * {v(o, k - j)}' for j in range(1, k + 1)])}) * {1 / k!r}")
            elif name == "LOG":
                e = (f"math.log({v(a, 0)}) if {v(a, 0)} > 0.0 else math.nan" if k == 0 else
                     f"({v(a, k)} - ({total([f'{j}.0 * {v(o, j)} * {v(a, k - j)}' for j in range(1, k)])})"
                     f" * {1 / k!r}) * (1.0 / {v(a, 0)})")
            elif name == "POW":
                e = (pow0_text(v(a, 0), c) if k == 0 else
                     f"({total([f'{c * (k - j) - j!r} * {v(a, k - j)} * {v(o, j)}' for j in range(k)])})"
                     f" * (1.0 / ({k}.0 * {v(a, 0)}))")
            else:  # pragma: no cover - the tape has no other variable instructions
                raise ValueError(f"no unrolled form for {name}")
            lines.append(f"{v(o, k)} = {e}")
        lines += _unrolled_solve(tape, k, v, variable)
    lines += [f"S[{i}, {k}] = v{i}_{k}" for i in range(nz) for k in range(1, order + 1)]
    body = [f"if p_order != {order}:", "    return False"]
    body += [f"c{slot} = S[{slot}, 0]" for slot in sorted(constants)] + lines + ["return True"]
    return ("import math\n\nimport numba\n\n\n"
            f"@numba.njit({SERIES_SIGNATURE!r}, cache=True, error_model='numpy')\n"
            "def series(t, S, acc, L, d, Mk, r, p_order):\n" + "\n".join("    " + line for line in body) + "\n")


def _unrolled_solve(tape: Tape, k: int, v, variable: set) -> list[str]:
    """Order ``k`` of ``M_0 a_k = f_k − Σ_{j≥1} M_j a_{k−j}`` in scalars (LDLᵀ of M_0 at k = 0, as in the loop
    form), then the state's coefficients ``k + 1``."""
    n = tape.n

    def m(i: int, j: int) -> int:
        return int(tape.mass[min(i, j), max(i, j)])

    lines = []
    if k == 0:
        lines += _ldl_lines(tape, lambda s: v(s, 0))
        lines += [f"d{i} = d[{i}]" for i in range(n)] + [f"L{i}_{j} = L[{i}, {j}]" for i in range(n) for j in range(i)]
    variable = variable | {tape.slot_t}  # as in the loop form: t's first coefficient is 1
    for i in range(n):
        terms = [f"{v(m(i, l_), j)} * a{l_}_{k - j}" for l_ in range(n) if m(i, l_) >= 0 and m(i, l_) in variable
                 for j in range(1, k + 1)]
        lines.append(f"r{i} = {v(int(tape.force[i]), k)}" + "".join(f" - {x}" for x in terms))
    for i in range(n):
        lines.append(f"r{i} = r{i}" + "".join(f" - L{i}_{j} * r{j}" for j in range(i)))
    for i in range(n - 1, -1, -1):
        lines.append(f"a{i}_{k} = r{i} * (1.0 / d{i})" + "".join(f" - L{j}_{i} * a{j}_{k}" for j in range(i + 1, n)))
    inv = repr(1 / (k + 1))
    for i in range(n):
        lines += [f"v{i}_{k + 1} = v{n + i}_{k} * {inv}", f"v{n + i}_{k + 1} = a{i}_{k} * {inv}"]
    if tape.power >= 0:
        lines.append(f"v{2 * n}_{k + 1} = {v(tape.power, k)} * {inv}")
    return lines


_SERIES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def compiled_series(tape: Tape, order: int | None = None):
    """The tape's ``series`` compiled by numba once per model and cached on disk like the other generated
    modules: written out for ``order`` (:func:`unrolled_source`) when that stays within :data:`UNROLL_TERMS`
    terms, else the loop form (:func:`series_source`, any order).

    Raises :class:`~lagrange.errors.BackendError` when numba is missing or the compilation fails."""
    cached = _SERIES.setdefault(tape, {})  # order (None: the loop form) -> compiled series
    if order not in cached:
        from .numba_backend import _require_numba, load_cached

        _require_numba("method='taylor' (the compiled series)")
        if order is not None and unrolled_terms(tape, order) <= UNROLL_TERMS:
            cached[order] = load_cached("taylor", unrolled_source(tape, order), "the Taylor series module").series
        else:
            cached[order] = cached[None] = cached.get(None) or load_cached("taylor", series_source(tape),
                                                                          "the Taylor series module").series
    return cached[order]
