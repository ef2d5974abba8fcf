"""Display of equations: the bounded trigonometric tidy-up, line wrapping and the conserved-momenta layout.

The tidy-up is checked against the untidied equations (the difference must vanish), and the numeric path
(derived Equations, generated source) against a twin system that was never printed.
"""

import unicodedata

import sympy as sp

import lagrange as lg
from lagrange.printing import (
    display_equations,
    format_equations,
    format_expression,
    format_momenta,
    latex_equations,
    tidy_trig,
)
from lagrange.simplification import is_zero

t = lg.t


def columns(line: str) -> int:
    """Terminal columns of a line (combining dots take none)."""
    return sum(1 for c in line if not unicodedata.combining(c))


def widest(text: str) -> int:
    return max(columns(line) for line in text.splitlines())


def test_tidy_trig_angle_sums_and_pythagoras():
    a, b = lg.coordinates("a b")
    m = lg.parameters("m")
    cases = {
        m * sp.sin(a) * sp.sin(b) + m * sp.cos(a) * sp.cos(b): m * sp.cos(a - b),
        sp.sin(a) * sp.cos(b) - sp.cos(a) * sp.sin(b): sp.sin(a - b),
        m * sp.sin(a) ** 2 * b.diff(t) + m * sp.cos(a) ** 2 * b.diff(t): m * b.diff(t),
    }
    for before, expected in cases.items():
        after = tidy_trig(before)
        assert is_zero(after - expected), (before, after)
        assert sp.count_ops(after) < sp.count_ops(before)
    # equal to the input in every case, and bounded: nothing is done above the size limit
    big = sp.sin(a) * sp.sin(b) + sp.cos(a) * sp.cos(b)
    assert tidy_trig(big, limit=3) is big
    eq = tidy_trig(sp.Eq(big, sp.sin(a) ** 2 + sp.cos(a) ** 2))
    assert is_zero(eq.lhs - sp.cos(a - b)) and eq.rhs == 1


def test_double_pendulum_printed_form_is_tidy_and_fits():
    from lagrange_problems.ch12_ex12_2 import system  # double pendulum with the string lengths as coordinates

    raw = system.equations()
    product = sp.sin(system.coordinates[0]) * sp.sin(system.coordinates[1])
    assert any(eq.has(product) for eq in raw)  # the derived (book) form has the products …
    shown = display_equations(system)
    assert len(shown) == len(raw)
    for before, after in zip(raw, shown):  # … the display form is the same equation
        assert is_zero((before.lhs - before.rhs) - (after.lhs - after.rhs))
        assert not after.has(product)
    text = str(system)
    assert text == format_equations(system, width=100)
    assert "cos(φ - θ)" in text and "sin(φ - θ)" in text
    assert "sin(φ)⋅sin(θ)" not in text and "cos(φ)⋅cos(θ)" not in text
    assert widest(text) <= 100
    assert all(widest(format_expression(eq, width=60)) <= 60 for eq in shown)


def _driven_string_pendulum():
    """A double pendulum on strings (holonomic constraints with multipliers), damped at the elbow and driven
    by a horizontal force F cos(ω t) on the first bob (explicit t, an input)."""
    theta, phi, r1, r2 = lg.coordinates("theta phi r1 r2")
    m1, m2, g, l1, l2, c, F, w = lg.parameters("m1 m2 g l1 l2 c F omega")
    X1, Y1 = r1 * sp.sin(theta), -r1 * sp.cos(theta)
    X2, Y2 = X1 + r2 * sp.sin(phi), Y1 - r2 * sp.cos(phi)
    b1, b2 = lg.Particle(m1, (X1, Y1)), lg.Particle(m2, (X2, Y2))
    return lg.System([theta, phi, r1, r2], bodies=[b1, b2], V=g * (m1 * Y1 + m2 * Y2),
                     rayleigh=c * (phi.diff(t) - theta.diff(t)) ** 2 / 2, forces=[lg.Force(b1, (F * sp.cos(w * t), 0))],
                     constraints=[r1 - l1, r2 - l2], name="driven string pendulum")


def test_display_never_touches_the_numeric_path(monkeypatch):
    monkeypatch.setenv("LAGRANGE_DERIVATION_CACHE", "0")
    params = dict(m1=1.0, m2=2.0, g=9.81, l1=1.0, l2=0.7, c=0.1, F=0.5, omega=2.0)
    never_printed = _driven_string_pendulum()
    reference_eqs = never_printed.derived
    reference_src = never_printed.compile(params).source

    printed = _driven_string_pendulum()
    before = sp.srepr(printed.derived.mass_matrix), sp.srepr(printed.derived.forcing)
    text = format_equations(printed) + format_momenta(printed) + latex_equations(printed)
    assert "cos(φ - θ)" in text
    assert (sp.srepr(printed.derived.mass_matrix), sp.srepr(printed.derived.forcing)) == before
    assert printed.derived == reference_eqs
    assert printed.compile(params).source == reference_src

    fresh = _driven_string_pendulum()  # printed before anything was derived
    format_equations(fresh)
    assert fresh.derived == reference_eqs and fresh.compile(params).source == reference_src


def test_wrapping_breaks_between_terms():
    xs = lg.coordinates(" ".join(f"x{i}" for i in range(12)))
    k = lg.parameters("k")
    lhs = sum((k * x.diff(t, 2) * sp.cos(x) for x in xs), sp.S.Zero)
    rhs = -sum((x.diff(t) ** 2 for x in xs), sp.S.Zero)
    text = format_expression(sp.Eq(lhs, rhs), width=50)
    lines = text.splitlines()
    assert widest(text) <= 50 and len(lines) > 6
    assert "= -" in text
    assert all(line.startswith("    ") for line in lines[2:] if line.strip())  # continuation lines indented
    # a product wider than the line is distributed over its sum; a lone wide quotient is cut by sympy
    wide = k * sum(xs, sp.S.Zero) ** 2 / sum((x ** 3 for x in xs), sp.S.One)
    assert widest(format_expression(wide, width=40)) <= 40
    assert widest(format_expression(k * sp.Add(*xs), width=30)) <= 30


def test_conserved_momenta_are_whole_equations():
    r, phi, z = lg.coordinates("r phi z")
    m, k = lg.parameters("m k")
    s = lg.System([r, phi, z], bodies=[lg.Particle(m, (r * sp.cos(phi), r * sp.sin(phi), z))], V=k * r**2 / 2)
    text = format_momenta(s)
    lines = text.splitlines()
    assert lines[0] == "ignorable coordinates (conserved momenta):"
    row = next(i for i, line in enumerate(lines) if "pᵩ = " in line)  # sympy's subscript φ
    assert "φ̇" in lines[row] and "m⋅r" in lines[row]  # the momentum on the line of its name
    assert lines[row - 1].strip() == "2"  # the square sits above it: one two-line picture, not two lines
    assert "p_z = m⋅z\u0307" in text
    assert format_momenta(lg.System([r], T=m * r.diff(t) ** 2 / 2, V=k * r**2 / 2)) == ""


def test_an_equation_too_long_to_read_is_summarized_unless_full(monkeypatch):
    """format_equations summarizes an equation above TERMINAL_NODES nodes in one line (naming how to get it
    whole) and prints the others; full=True prints every one."""
    import lagrange.printing as printing
    from lagrange import Particle, System, coordinates, parameters

    x, y = coordinates("x y")
    m, k = parameters("m k")
    V = k * x**2 / 2 + sum(sp.cos(y) ** j / (j + 1) for j in range(1, 40))  # a long force on y, a short one on x
    s = System([x, y], bodies=[Particle(m, (x, y))], V=V)
    long_size = printing._tree_size(s.equations()[1], 10**6)
    short_size = printing._tree_size(s.equations()[0], 10**6)
    assert short_size < long_size
    monkeypatch.setattr(printing, "TERMINAL_NODES", (short_size + long_size) // 2)
    text = printing.format_equations(s)
    blocks = text.split("[y]")
    assert "too long to read here" not in blocks[0] and "k" in blocks[0]  # x's equation printed
    assert "too long to read here" in blocks[1] and "lagrange derive --full" in blocks[1]
    full = printing.format_equations(s, full=True)
    assert "too long to read here" not in full
    assert full.count("cos") == 38  # ∂V/∂y: every term of the sum, j = 2 … 39 (j = 1 gives sin y alone)
