r"""A model's right-hand side as a *tape*: straight-line elementary operations on numbered slots.

The tape is what the Taylor integrator (:mod:`lagrange.integrate.taylor`) interprets: no code is generated
or compiled per model, so a new model costs only its derivation and this translation (milliseconds), and
the interpreter (:file:`lagrange/integrate/_taylor_interp.c`) is compiled once per machine (or at install
time). The integrator reaches it through the compiled model (:meth:`NumericModel.taylor_tape
<lagrange.codegen.numeric.NumericModel.taylor_tape>`).

Built from the same CSE as every backend (:func:`lagrange.codegen.cse.fuse`: M's upper triangle, f and,
for non-conservative systems, the power dh/dt of the work integral). Slots::

    0 .. 2n−1      the state y = [q, q̇]
    2n             the work integral (non-conservative systems only)
    slot_t         the time t
    the rest       parameters, numbers and intermediate results

Supported operations: ``+ − × ÷``, integer and real powers (``sqrt``), ``exp``, ``log``, ``sin``, ``cos``,
``tan``, ``sinh``, ``cosh``, ``tanh``; each instruction is classified *constant* (it depends on parameters
and numbers only; evaluated once per integration) or *variable*. Anything else — ``sign``, ``Abs``,
``Piecewise``, ``atan2``, … — raises :class:`TapeError` naming the function: the Taylor method needs an
analytic right-hand side (use an adaptive Runge–Kutta method for those systems).
"""

from __future__ import annotations

import weakref
from dataclasses import field

import numpy as np
import sympy as sp

from ..derive.equations import Equations
from ..errors import LagrangeError
from ..records import record

__all__ = ["Tape", "TapeError", "build_tape", "tape_of", "OPCODES"]

#: opcode numbers, shared with the C interpreter (:file:`lagrange/integrate/_taylor_interp.c`) and
#: :mod:`lagrange.integrate._taylor_loop`
OPCODES = dict(zip(("LOADC", "LOADP", "ADD", "ADDC", "SUB", "SUBVC", "SUBCV", "MUL", "MULC", "DIV", "DIVVC",
                    "DIVCV", "NEG", "SINCOS", "EXP", "LOG", "POW"), range(17)))
_O = OPCODES


class TapeError(LagrangeError, TypeError):
    """The right-hand side holds an operation the Taylor method cannot expand (named in the message)."""


@record(frozen=True, eq=False)
class Tape:
    """A model's tape (see the module docstring). ``const_code``/``code`` are (k, 4) int64 rows
    ``(op, a, b, out)``; ``const_vals``/``consts`` the matching float64 constants (numbers, exponents)."""

    n: int
    nz: int
    n_slots: int
    slot_t: int
    const_code: np.ndarray
    const_vals: np.ndarray
    code: np.ndarray
    consts: np.ndarray
    mass: np.ndarray  # (n, n) int64, upper triangle slots, −1 = structural zero
    force: np.ndarray  # (n,) int64
    power: int  # slot of dh/dt, −1 for conservative systems

    @property
    def size(self) -> int:
        """Number of instructions run at every order of every step."""
        return int(self.code.shape[0])


@record
class _Builder:
    n_params: int
    next_slot: int
    var: set = field(default_factory=set)
    memo: dict = field(default_factory=dict)
    rows: list = field(default_factory=list)  # (is_var, op, a, b, out, const)

    def new(self) -> int:
        self.next_slot += 1
        return self.next_slot - 1

    def emit(self, op: str, a: int = 0, b: int = 0, c: float = 0.0, *, var: bool, out: int | None = None) -> int:
        key = ("op", op, a, b, float(c))  # the same operation on the same slots again (x*c in two CSE terms)
        if out is None and op not in ("LOADC", "LOADP") and key in self.memo:
            return self.memo[key]
        o = self.new() if out is None else out
        if out is None:
            self.memo[key] = o
        self.rows.append((var, _O[op], a, b, o, float(c)))
        if var:
            self.var.add(o)
        return o

    def number(self, value: float) -> int:
        key = ("num", float(value))
        if key not in self.memo:
            self.memo[key] = self.emit("LOADC", c=float(value), var=False)
        return self.memo[key]

    # --- arithmetic with the constant/variable classification ---
    def binary(self, a: int, b: int, vv: str, vc: str, cv: str | None = None) -> int:
        """``a ∘ b`` as ``vv`` when both operands are variable or both constant, ``vc`` for variable ∘ constant,
        ``cv`` for constant ∘ variable — or, for a commutative ∘ (``cv`` None), ``vc`` with the operands swapped."""
        va, vb = a in self.var, b in self.var
        if va == vb:
            return self.emit(vv, a, b, var=va)
        if cv is None and not va:
            a, b, va = b, a, True
        return self.emit(vc if va else cv, a, b, var=True)

    def add(self, a: int, b: int) -> int:
        return self.binary(a, b, "ADD", "ADDC")

    def sub(self, a: int, b: int) -> int:
        return self.binary(a, b, "SUB", "SUBVC", "SUBCV")

    def mul(self, a: int, b: int) -> int:
        return self.binary(a, b, "MUL", "MULC")

    def div(self, a: int, b: int) -> int:
        return self.binary(a, b, "DIV", "DIVVC", "DIVCV")

    def unary(self, op: str, a: int, c: float = 0.0) -> int:
        return self.emit(op, a, c=c, var=a in self.var)

    def sincos(self, a: int) -> tuple[int, int]:
        key = ("sincos", a)
        if key not in self.memo:
            s, c = self.new(), self.new()
            self.rows.append((a in self.var, _O["SINCOS"], a, c, s, 0.0))
            if a in self.var:
                self.var.update((s, c))
            self.memo[key] = (s, c)
        return self.memo[key]

    def power(self, base: int, e) -> int:
        if e.is_Integer:
            k = int(e)
            if k == 0:
                return self.number(1.0)
            r = self._int_power(base, abs(k))
            return r if k > 0 else self.div(self.number(1.0), r)
        return self.unary("POW", base, float(e))

    def _int_power(self, base: int, k: int) -> int:
        result, sq = None, base
        while k:
            if k & 1:
                result = sq if result is None else self.mul(result, sq)
            k >>= 1
            if k:
                sq = self.mul(sq, sq)
        return result

    # --- expressions ---
    def expr(self, e) -> int:
        if e in self.memo:
            return self.memo[e]
        slot = self._expr(e)
        self.memo[e] = slot
        return slot

    def _expr(self, e) -> int:
        if e.is_Number:
            return self.number(float(e))
        if e.is_NumberSymbol:
            return self.number(float(e.evalf(17)))
        if e.is_Add:
            terms = list(e.args)
            slot = None
            for term in terms:
                neg = term.is_Mul and term.args[0] == -1
                s = self.expr(sp.Mul(*term.args[1:]) if neg else term)
                if slot is None:
                    slot = self.unary("NEG", s) if neg else s
                else:
                    slot = self.sub(slot, s) if neg else self.add(slot, s)
            return slot
        if e.is_Mul:
            num, den = [], []
            for f in e.args:  # u**(-k) (integer k) divides; u**(-α) stays one power: one recurrence, not two
                if f.is_Pow and f.exp.is_Integer and f.exp.is_negative:
                    den.append(self.expr(sp.Pow(f.base, -f.exp)))
                else:
                    num.append(self.expr(f))
            top = num[0] if num else self.number(1.0)
            for s in num[1:]:
                top = self.mul(top, s)
            if not den:
                return top
            bottom = den[0]
            for s in den[1:]:
                bottom = self.mul(bottom, s)
            return self.div(top, bottom)
        if e.is_Pow:
            if e.exp.is_Number:
                return self.power(self.expr(e.base), e.exp)
            return self.unary("EXP", self.expr(e.exp * sp.log(e.base)))  # b**x = exp(x log b)
        return self._function(e)

    def _function(self, e) -> int:
        f = e.func
        if f in (sp.sin, sp.cos, sp.tan):
            s, c = self.sincos(self.expr(e.args[0]))
            return s if f is sp.sin else c if f is sp.cos else self.div(s, c)
        if f is sp.exp:
            return self.unary("EXP", self.expr(e.args[0]))
        if f is sp.log and len(e.args) == 1:
            return self.unary("LOG", self.expr(e.args[0]))
        if f in (sp.sinh, sp.cosh, sp.tanh):
            u = e.args[0]
            return self.expr({sp.sinh: (sp.exp(u) - sp.exp(-u)) / 2, sp.cosh: (sp.exp(u) + sp.exp(-u)) / 2,
                              sp.tanh: (sp.exp(2 * u) - 1) / (sp.exp(2 * u) + 1)}[f])
        raise _refusal(f"{getattr(f, '__name__', f)}(...)", "the equations")  # _check_analytic names the place


_ANALYTIC = (sp.sin, sp.cos, sp.tan, sp.exp, sp.log, sp.sinh, sp.cosh, sp.tanh)


def _check_analytic(eqs: Equations) -> None:
    """Name the first function the tape cannot expand, in the user's symbols and with the equation it is in."""
    from ..model.coordinates import coordinate_name

    names = [coordinate_name(c) for c in eqs.coordinates]
    if eqs.has_quadrature:
        raise TapeError("the equations hold an integral evaluated by quadrature (lagrange.codegen.quadrature), "
                        "which the Taylor method and heyoka cannot expand; use an adaptive Runge-Kutta method such "
                        "as method='DOP853' for this system")
    places = [(f"the generalized force of {names[i]}", e) for i, e in enumerate(eqs.forcing)]
    places += [(f"the mass matrix entry M[{names[i]}, {names[j]}]", eqs.mass_matrix[i, j])
               for i in range(eqs.n) for j in range(i, eqs.n)]
    if not eqs.is_conservative:
        places.append(("the power dh/dt of the work integral", eqs.jacobi_rate))
    for where, e in places:
        for f in sorted(sp.sympify(e).atoms(sp.Function), key=sp.default_sort_key):
            if f.func not in _ANALYTIC:
                raise _refusal(str(f), where)


def _refusal(what: str, where: str) -> TapeError:
    return TapeError(f"the Taylor method cannot expand {what} in {where} (it needs an analytic right-hand side: "
                     f"+ - * / powers exp log sin cos tan sinh cosh tanh); use an adaptive Runge-Kutta method such "
                     f"as method='DOP853' for this system")


def build_tape(eqs: Equations) -> Tape:
    """The tape of an unconstrained system's ``[q̇, q̈(, dh/dt)]`` (see the module docstring).

    Raises
    ------
    TapeError
        The system has constraints, or its equations hold a non-analytic function (named).
    """
    if eqs.m or eqs.is_rough:
        raise TapeError("the Taylor method integrates unconstrained systems (this one has "
                        f"{eqs.m} constraint(s)): use method='DOP853' or the other scipy methods")
    n = eqs.n
    conservative = eqs.is_conservative
    _check_analytic(eqs)
    extra = () if conservative else (eqs.jacobi_rate,)
    from .cse import fuse  # (here: a run that loads its tape from the cache never needs the CSE)

    fused, red_extra = fuse(eqs, extra=extra)
    nz = 2 * n + (0 if conservative else 1)
    slot_t = nz
    b = _Builder(n_params=len(eqs.numeric_parameters), next_slot=nz + 1)
    b.var.update(range(nz + 1))
    b.memo.update({sp.Symbol(f"y{i}", real=True): i for i in range(2 * n)})
    b.memo[sp.Symbol("t", real=True)] = slot_t
    for k in range(b.n_params):
        b.memo[sp.Symbol(f"p{k}", real=True)] = b.emit("LOADP", k, var=False)
    for sym, e in fused.temporaries:
        b.memo[sym] = b.expr(e)
    mass = -np.ones((n, n), dtype=np.int64)
    for (i, j), e in fused.mass_upper.items():
        mass[i, j] = b.expr(e)
    force = np.empty(n, dtype=np.int64)
    for i, e in enumerate(fused.forcing):
        force[i] = b.expr(e)
    power = -1
    if red_extra:
        power = b.expr(red_extra[0])

    def arrays(rows):
        code = np.array([r[1:5] for r in rows], dtype=np.int64).reshape(-1, 4)
        return np.ascontiguousarray(code), np.array([r[5] for r in rows], dtype=float)

    const_code, const_vals = arrays([r for r in b.rows if not r[0]])
    code, consts = arrays([r for r in b.rows if r[0]])
    return Tape(n=n, nz=nz, n_slots=b.next_slot, slot_t=slot_t, const_code=const_code, const_vals=const_vals,
                code=code, consts=consts, mass=mass, force=force, power=power)


_TAPES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_SCALARS = ("n", "nz", "n_slots", "slot_t", "power")
_ARRAYS = {"const_code": np.int64, "const_vals": np.float64, "code": np.int64, "consts": np.float64,
           "mass": np.int64, "force": np.int64}


def _tape_arrays(tape: Tape) -> dict[str, np.ndarray]:
    return {name: np.asarray(getattr(tape, name), dtype=np.int64) for name in _SCALARS} | \
        {name: getattr(tape, name) for name in _ARRAYS}


def _tape_valid(a: dict[str, np.ndarray]) -> bool:
    """Whether stored arrays make a well-formed tape (names, types, shapes; every slot inside the tape)."""
    if set(a) != set(_SCALARS) | set(_ARRAYS) or any(a[k].shape != () or a[k].dtype != np.int64 for k in _SCALARS):
        return False
    if any(a[k].dtype != dtype for k, dtype in _ARRAYS.items()):
        return False
    n, n_slots = int(a["n"]), int(a["n_slots"])
    code_ok = all(a[c].ndim == 2 and a[c].shape[1] == 4 and a[v].shape == (a[c].shape[0],)
                  for c, v in (("const_code", "const_vals"), ("code", "consts")))
    slots = np.concatenate([a["const_code"][:, 1:].ravel(), a["code"][:, 1:].ravel(), a["force"],
                            a["mass"].ravel(), [a["power"]]]) if code_ok else np.zeros(0)
    return (code_ok and n > 0 and a["mass"].shape == (n, n) and a["force"].shape == (n,)
            and bool(np.all((slots >= -1) & (slots < n_slots))) and 0 <= int(a["slot_t"]) < n_slots)


def tape_of(eqs: Equations) -> Tape:
    """:func:`build_tape` of ``eqs``, built once per Equations (equal equations share it) and kept in the
    on-disk cache (:func:`lagrange.codegen.derivation_cache.cached_arrays`, entry ``tape_<key>.arrays``): a
    re-run of the same model in a new process loads it instead of running the CSE again."""
    if eqs not in _TAPES:
        from .derivation_cache import cached_arrays

        a = cached_arrays(eqs, "tape", "", lambda: _tape_arrays(build_tape(eqs)), _tape_valid)
        _TAPES[eqs] = Tape(**{k: int(a[k]) for k in _SCALARS},
                           **{k: np.ascontiguousarray(a[k]) for k in _ARRAYS})
    return _TAPES[eqs]
