"""Plots leave the user's matplotlib backend and pyplot state alone, put each coordinate on its own axes,
accept ``ax=`` and a coordinate selection, label λ by constraint name, and animate inline."""

import csv

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest

from lagrange import Holonomic, LagrangeError, Particle, System, coordinates, parameters, t
from lagrange.examples import n_link_pendulum
from lagrange.plot import InlineAnimation, animate, plot_trajectory, plot_work_precision


@pytest.fixture(scope="module")
def chain():
    s = n_link_pendulum(2)
    return s, s.simulate(1, {"q1": 1, "q2": 0.5, "q1_dot": 0, "q2_dot": 0}, {"g": 9.81}, n_points=41)


@pytest.fixture(scope="module")
def pendulum():
    """A pendulum in Cartesian coordinates held by the constraint named "string"."""
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(x**2 + y**2 - l**2, "string")], name="Cartesian pendulum")
    th0 = 0.7
    sol = s.simulate(2, {x: np.sin(th0), y: -np.cos(th0), x.diff(t): 0, y.diff(t): 0}, {m: 1, g: 9.81, l: 1},
                     n_points=41)
    return s, sol


@pytest.fixture
def other_backend():
    """Run with the PDF backend (not Agg): a plot that calls ``matplotlib.use("Agg")`` would change it."""
    before = matplotlib.get_backend()
    plt.close("all")
    matplotlib.use("pdf")
    yield "pdf"
    plt.close("all")
    matplotlib.use(before)


def _lines(ax):
    return [(line.get_label(), line.get_xdata(), line.get_ydata()) for line in ax.get_lines()]


def test_writing_a_png_keeps_the_backend_and_pyplot_state(chain, other_backend, tmp_path):
    s, sol = chain
    fig = sol.plot(tmp_path / "a.png", dpi=40)
    assert matplotlib.get_backend() == other_backend
    assert plt.get_fignums() == []  # the figure is not in pyplot's list (nothing shows up later inline)
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert fig._suptitle.get_text() == "2-link pendulum"  # the system's name, not the file name
    path = animate(s, sol, tmp_path / "a.gif", frames=3)
    assert path.read_bytes()[:3] == b"GIF"
    assert matplotlib.get_backend() == other_backend and plt.get_fignums() == []
    problem = {"name": "toy", "title": "two curves", "energy": None,
               "curves": [{"kind": "lagrange", "backend": "numba", "label": "DOP853",
                           "points": [{"error": 1e-6, "wall": 1e-3, "nfev": 100}, {"error": 1e-9, "wall": 3e-3,
                                                                                   "nfev": 300}]}]}
    plot_work_precision(problem, tmp_path / "wp.png", dpi=30)
    assert matplotlib.get_backend() == other_backend and plt.get_fignums() == []
    assert (tmp_path / "wp.png").stat().st_size > 500


def test_one_panel_per_coordinate_with_shared_time(chain):
    s, sol = chain
    fig = plot_trajectory(sol)
    try:
        left = fig.subfigs[0].axes
        assert len(left) == 2
        for i, ax in enumerate(left):
            ((label, x, yv),) = _lines(ax)
            assert label == ["q1", "q2"][i] and ax.get_ylabel() == label
            assert np.array_equal(x, sol.t) and np.array_equal(yv, sol.y[:, i])
        assert left[0].get_shared_x_axes().joined(left[0], left[1])
    finally:
        plt.close(fig)


def test_coordinate_selection_by_name_function_and_index(chain):
    s, sol = chain
    q1, q2 = s.coordinates
    for sel in (["q2"], [q2], [1], q2, "q2"):
        fig = plot_trajectory(sol, coordinates=sel)
        try:
            ((label, _, yv),) = _lines(fig.subfigs[0].axes[0])
            assert len(fig.subfigs[0].axes) == 1 and label == "q2" and np.array_equal(yv, sol["q2"])
        finally:
            plt.close(fig)
    with pytest.raises(LagrangeError, match="'q3'.*coordinates: q1, q2") as info:
        plot_trajectory(sol, coordinates=["q1", "q3"])
    assert isinstance(info.value, ValueError)
    with pytest.raises(LagrangeError, match="selects nothing"):
        plot_trajectory(sol, coordinates=[])


def test_user_axes(chain):
    s, sol = chain
    fig, ax = plt.subplots()
    try:
        assert sol.plot(ax=ax) is fig
        assert [label for label, *_ in _lines(ax)] == ["q1", "q2"]
        assert len(fig.axes) == 1  # nothing else drawn
    finally:
        plt.close(fig)
    fig, axs = plt.subplots(2, 1)
    try:
        sol.plot(ax=axs, coordinates=["q2", "q1"])
        assert np.array_equal(_lines(axs[0])[0][2], sol["q2"]) and np.array_equal(_lines(axs[1])[0][2], sol["q1"])
        with pytest.raises(LagrangeError, match="2 axes for 1 selected"):
            sol.plot(ax=list(axs), coordinates=["q1"])
    finally:
        plt.close(fig)


def test_multipliers_labelled_by_constraint_name_in_plot_and_csv(pendulum, tmp_path):
    s, sol = pendulum
    fig = sol.plot(tmp_path / "p.png", dpi=30)
    lam_ax = fig.subfigs[1].axes[-1]
    ((label, _, lam),) = _lines(lam_ax)
    assert label == "λ[string]" and np.array_equal(lam, sol.multiplier("string"))
    # independent truth: with φ = x² + y² − l², Aᵀλ = 2λ(x, y) is the string force, −2λl = m g cos θ + m l θ̇²
    x, y, xd, yd = (sol.y[:, i] for i in range(4))
    tension = 9.81 * (-y) + (xd**2 + yd**2)
    assert np.allclose(-2 * lam, tension, atol=1e-6)
    path = sol.to_csv(tmp_path / "p.csv")
    with path.open() as fh:
        rows = list(csv.DictReader(fh))
    assert list(rows[0])[-1] == "lambda_string"
    assert np.allclose([float(r["lambda_string"]) for r in rows], lam, rtol=1e-15)


def test_inline_animation_is_html_with_every_frame(chain, other_backend):
    s, sol = chain
    anim = animate(s, sol, inline=True, frames=5, size=3)
    assert isinstance(anim, InlineAnimation) and anim.frames == 5
    html = anim._repr_html_()
    assert html.count("data:image/png;base64") == 5  # the frames are embedded, nothing to fetch
    assert matplotlib.get_backend() == other_backend and plt.get_fignums() == []


def test_trajectory_plot_system_without_name_uses_given_title(tmp_path):
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2)
    sol = s.simulate(1, {x: 1, x.diff(t): 0}, {}, n_points=11)
    assert sol.plot(tmp_path / "x.png", dpi=30)._suptitle.get_text() == "trajectory"
    assert sol.plot(tmp_path / "x.png", title="oscillator", dpi=30)._suptitle.get_text() == "oscillator"
    assert np.allclose(sol[x], np.cos(sol.t), atol=1e-6)
