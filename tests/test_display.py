"""Rich display (lagrange.display) of results in Jupyter, checked against independently computed values,
and the messages for missing optional dependencies."""

import sys
from html.parser import HTMLParser

import numpy as np
import pytest
import sympy as sp

from lagrange import (
    Holonomic,
    LagrangeError,
    Particle,
    System,
    coordinates,
    hamiltonian,
    linearize,
    normal_modes,
    parameters,
    t,
)
from lagrange.errors import BackendError, SweepError
from lagrange.examples import n_link_pendulum
from lagrange.sweep import EnsembleResult


class _Cells(HTMLParser):
    """The text of every table cell, row by row."""

    def __init__(self):
        super().__init__()
        self.rows, self._cell = [], None

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = ""

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self.rows[-1].append(self._cell)
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data


def _table(html: str) -> list[list[str]]:
    p = _Cells()
    p.feed(html)
    return p.rows


def test_trajectory_summary_table_of_a_constrained_run():
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(x**2 + y**2 - l**2, "string")], name="pendulum <Cartesian>")
    sol = s.simulate(1.5, {x: 0.6, y: -0.8, x.diff(t): 0, y.diff(t): 0}, {m: 1, g: 9.81, l: 1}, n_points=31)
    rows = dict(_table(sol._repr_html_()))
    assert rows["system"] == "pendulum <Cartesian>"  # escaped in the HTML, restored by the parser
    assert "<Cartesian>" not in sol._repr_html_()
    assert rows["coordinates"] == "x, y" and rows["method"] == sol.method
    assert rows["points"] == "31" and rows["time span"] == "[0, 1.5]"
    assert rows["status"].startswith("ok") and rows["rhs evaluations"] == str(sol.nfev)
    # the value shown is the run's own energy_error(), and energy is conserved: it must be tiny
    shown = float(rows["power-balance residual (relative)" if sol.work is not None else "energy drift (relative)"])
    assert shown == float(f"{sol.energy_error():.3e}") and shown < 1e-7
    h = sol.energy
    assert np.max(np.abs(h - h[0])) / np.max(np.abs(h)) < 1e-7
    assert rows["constraints (λ)"] == "string"
    r = np.hypot(sol["x"], sol["y"])
    assert float(rows["max constraint violation"]) >= np.max(np.abs(r**2 - 1)) * 0.999


def test_failed_run_says_so():
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2, name="oscillator")
    sol = s.simulate(1, {x: 1, x.diff(t): 0}, {}, n_points=5)
    import dataclasses

    failed = dataclasses.replace(sol, success=False, message="step size too small at t=0.5")
    assert dict(_table(failed._repr_html_()))["status"] == "FAILED: step size too small at t=0.5"


def test_linear_model_latex_shows_the_double_pendulum_matrices():
    lin = linearize(n_link_pendulum(2))
    tex = lin._repr_latex_()
    g = sp.Symbol("g")
    # closed form for unit masses and rods, absolute angles: a = [[2, 1], [1, 1]], b = 0, c = diag(2g, g)
    assert sp.latex(sp.Matrix([[2, 1], [1, 1]])) in tex
    assert sp.latex(sp.Matrix([[2 * g, 0], [0, g]])) in tex
    assert sp.latex(sp.zeros(2, 2)) in tex
    assert tex.startswith("$") and tex.endswith("$")


def test_modes_table_matches_the_closed_form():
    modes = normal_modes(linearize(n_link_pendulum(2)), {"g": 9.81})
    rows = _table(modes._repr_html_())
    header, body = rows[0], rows[1:]
    assert header == ["mode", "ω", "period 2π/ω", "shape: s1", "shape: s2"]
    # ω² = g (2 ∓ √2); shapes (1, √2) and (−1, √2) up to scale, shown with the largest component 1
    omega = np.sqrt(9.81 * np.array([2 - np.sqrt(2), 2 + np.sqrt(2)]))
    for k, row in enumerate(body):
        assert float(row[1]) == pytest.approx(omega[k], rel=1e-5)
        assert float(row[2]) == pytest.approx(2 * np.pi / omega[k], rel=1e-5)
    assert [float(v) for v in body[0][3:]] == pytest.approx([1 / np.sqrt(2), 1], rel=1e-3)
    assert [float(v) for v in body[1][3:]] == pytest.approx([-1 / np.sqrt(2), 1], rel=1e-3)


def test_hamiltonian_latex():
    form = hamiltonian(n_link_pendulum(1))
    tex = form._repr_latex_()
    (q,), (p,) = form.q, form.p
    (g,) = [s_ for s_ in form.H.free_symbols if s_.name == "g"]
    assert sp.simplify(form.H - (p**2 / 2 - g * sp.cos(q))) == 0  # the pendulum's H for m = l = 1
    assert f"H &= {sp.latex(form.H)}" in tex
    assert rf"\dot{{{sp.latex(p)}}} &= {sp.latex(form.pdot[0])}" in tex
    assert sp.simplify(form.pdot[0] + g * sp.sin(q)) == 0


def test_ensemble_summary():
    res = EnsembleResult(t=np.linspace(0, 2, 5), y=np.zeros((3, 5, 2)), nfev=np.array([10, 30, 20]),
                         nsteps=np.array([1, 3, 2]), status=np.array([0, -1, 0]),
                         messages=("ok", "step <too> small", "ok"), method="DOP853")
    rows = dict(_table(res._repr_html_()))
    assert rows["members"] == "3" and rows["reached the end"] == "2 of 3"
    assert rows["first failure"] == "step <too> small"
    assert rows["rhs evaluations per member"] == "min 10, median 20, max 30"


def test_missing_pandas_names_the_extra(monkeypatch):
    from lagrange.sweep.table import require_pandas

    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(SweepError, match=r'pip install "lagrange-dynamics\[sweep\]"') as info:
        require_pandas()
    assert isinstance(info.value, LagrangeError)


def test_missing_numba_names_the_extra(monkeypatch):
    from lagrange.codegen.numba_backend import cache_key
    from lagrange.integrate.compiled import loop_backend

    monkeypatch.setitem(sys.modules, "numba", None)
    with pytest.raises(BackendError, match=r'pip install "lagrange-dynamics\[fast\]"'):
        loop_backend("compiled", backend="auto", model=None)
    with pytest.raises(BackendError, match=r'pip install "lagrange-dynamics\[fast\]"'):
        cache_key("source")


def test_equilibrium_latex_names_positions_and_multipliers():
    """A constrained equilibrium shows its positions and λ by constraint name (a name with LaTeX specials is
    escaped); the values are those the analysis found (Cartesian pendulum: y = −l, λ = −m g)."""
    from lagrange import equilibria

    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "rod_1&2")])
    bottom = next(e for e in equilibria(s) if e[y] == -l)
    text = bottom._repr_latex_()
    assert text.startswith("$") and text.endswith("$")
    assert "y &= - l" in text and "x &= 0" in text
    assert r"\lambda_{\text{rod\_1\&2}} &= - g m" in text


def test_potential_series_latex_by_degree():
    """Wells §5.10: V = k x²/2 + a x³ about x = 0 to order 3 shows each degree (the series' own terms)."""
    from lagrange import expand_potential

    x = sp.Symbol("x")
    k, a = sp.symbols("k a")
    series = expand_potential(k * x**2 / 2 + a * x**3, {x: 0}, order=3)
    text = series._repr_latex_()
    assert text.startswith("$") and text.endswith("$")
    assert rf"V_{{2}} &= {sp.latex(k * x**2 / 2)}" in text and rf"V_{{3}} &= {sp.latex(a * x**3)}" in text
    assert r"\text{about } x = 0" in text and "order } 3" in text


def test_greenspan_summary_table():
    """A Greenspan run's summary as a table: fall, P1's drift (here a P1 moving by (0.3, −0.1))."""
    from lagrange.discrete.greenspan import summarize

    tt = np.linspace(0.0, 2.0, 5)
    vertices = np.zeros((5, 4, 3))
    vertices[:, 1:, 2] = 1.0
    vertices[:, 0, 0] = 0.15 * tt
    vertices[:, 0, 1] = -0.05 * tt
    rows = _table(summarize(tt, vertices, False, None)._repr_html_())
    cells = {r[0]: r[1] for r in rows if len(r) == 2}
    assert cells["fell"] == "no" and cells["P1 drift"] == "(+0.300000, -0.100000)"
    assert cells["output times"].startswith("5, t = 0")
