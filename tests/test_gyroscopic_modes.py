"""normal_modes with a gyroscopic or damping matrix b: frequencies from the roots of |a λ² + b λ + c| = 0."""

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest
import sympy as sp

from lagrange import (
    AnalysisError,
    LagrangeError,
    Particle,
    System,
    characteristic_roots,
    coordinates,
    linearize,
    normal_modes,
    oscillations_about_steady_motion,
    parameters,
    routhian,
    t,
)
from lagrange.display import modes_html

G, L = 9.81, 1.3


def spherical_pendulum():
    th, ph = coordinates("theta phi")
    m, g, l = parameters("m g l")
    pos = (l * sp.sin(th) * sp.cos(ph), l * sp.sin(th) * sp.sin(ph), -l * sp.cos(th))
    return System([th, ph], bodies=[Particle(m, pos)], V=m * g * pos[2]), th, ph


def conical(th0):
    """The spherical pendulum linearized about conical motion at θ0 (φ̇0² = g/(l cos θ0))."""
    s, th, ph = spherical_pendulum()
    w = np.sqrt(G / (L * np.cos(th0)))
    return s, linearize(s, {th: th0, ph: 0}, velocities={ph.diff(t): w}, params={"m": 0.7, "g": G, "l": L})


def conical_closed_form(th0):
    """ω² = (g/l)(1 + 3cos²θ0)/cos θ0 (perturb θ = θ0 + s with p_φ fixed: ω² = R''(θ0)/(m l²))."""
    return np.sqrt(G / L * (1 + 3 * np.cos(th0) ** 2) / np.cos(th0))


@pytest.mark.parametrize("th0", [0.2, 0.6, 1.1])
def test_conical_pendulum_against_closed_form_and_roots(th0):
    _, lin = conical(th0)
    a, b, c = lin.numeric()
    assert np.abs(b - b.T).max() > 0.1  # the gyroscopic coupling θ–φ is there
    modes = normal_modes(lin)
    assert modes.kind == "gyroscopic"
    assert modes.omega == pytest.approx([0.0, conical_closed_form(th0)], rel=1e-10, abs=1e-9)
    lam = characteristic_roots(lin)
    assert np.sort(np.abs(lam.imag))[-1] == pytest.approx(modes.omega[-1], rel=1e-12)
    # the value (a, c) alone would give, which the analysis used to report, is far from it
    assert np.sqrt(c[0, 0] / a[0, 0]) < 0.8 * modes.omega[-1]
    assert modes.periods[-1] == pytest.approx(2 * np.pi / conical_closed_form(th0), rel=1e-10)
    assert modes.periods[0] == np.inf


def test_conical_pendulum_routhian_agrees():
    """A second formulation: the Routhian reduces out φ; its 1-D oscillation has the same frequency."""
    th0 = 0.6
    s, th, ph = spherical_pendulum()
    R = routhian(s, [ph])
    (p,) = R.momenta
    w = np.sqrt(G / (L * np.cos(th0)))
    vals = {"m": 0.7, "g": G, "l": L}
    lin = oscillations_about_steady_motion(R, {th: th0})
    subs = {sym: vals[sym.name] for sym in s.parameters} | {p: 0.7 * L**2 * np.sin(th0) ** 2 * w}
    a, c = float(lin.a[0, 0].subs(subs)), float(lin.c[0, 0].subs(subs))
    assert np.sqrt(c / a) == pytest.approx(conical_closed_form(th0), rel=1e-10)
    assert normal_modes(conical(th0)[1]).omega[-1] == pytest.approx(np.sqrt(c / a), rel=1e-10)


def rotating_particle(k1, k2, Omega=2.0, m=1.5):
    """A particle on springs k1 (along x), k2 (along y) in a frame rotating at Ω: b = 2mΩ [[0, −1], [1, 0]]."""
    x, y = coordinates("x y")
    co, si = sp.cos(Omega * t), sp.sin(Omega * t)
    s = System([x, y], bodies=[Particle(m, (x * co - y * si, x * si + y * co))], V=(k1 * x**2 + k2 * y**2) / 2)
    return linearize(s, {x: 0, y: 0}, params={})


def test_rotating_frame_isotropic_gyroscopic_stabilization():
    """Isotropic spring k seen from a frame rotating at Ω: frequencies |ω0 ± Ω| (ω0² = k/m), also when Ω > ω0
    makes c = k − mΩ² negative (stable by the gyroscopic coupling alone)."""
    m, Omega = 1.5, 2.0
    for k in (24.0, 1.5):  # ω0 = 4 > Ω, then ω0 = 1 < Ω
        lin = rotating_particle(k, k, Omega, m)
        w0 = np.sqrt(k / m)
        modes = normal_modes(lin)
        assert modes.kind == "gyroscopic"
        assert modes.omega == pytest.approx(sorted([abs(w0 - Omega), w0 + Omega]), rel=1e-12)
    assert np.all(np.linalg.eigvalsh(lin.numeric()[2]) < 0)  # the last one: c negative definite


def test_rotating_frame_unstable_band_is_refused():
    """Springs k1 < mΩ² < k2 (Ω between the two spring frequencies): a root with a positive real part."""
    m, Omega = 1.0, 2.0
    lin = rotating_particle(3.0, 6.0, Omega, m)
    assert np.max(characteristic_roots(lin).real) > 0.1
    with pytest.raises(LagrangeError, match="unstable"):
        normal_modes(lin)
    stable = normal_modes(rotating_particle(20.0, 30.0, Omega, m))  # both springs stiff: stable, 2 frequencies
    lam = characteristic_roots(rotating_particle(20.0, 30.0, Omega, m))
    assert stable.omega == pytest.approx(np.sort(np.abs(lam.imag))[1::2], rel=1e-12)


def test_gyroscopic_motion_matches_simulation():
    """Modes.motion of a gyroscopic model is the exact linear solution; fit/normal_coordinates refuse."""
    x, y = coordinates("x y")
    m, Omega, k1, k2 = 1.5, 2.0, 20.0, 30.0
    co, si = sp.cos(Omega * t), sp.sin(Omega * t)
    s = System([x, y], bodies=[Particle(m, (x * co - y * si, x * si + y * co))], V=(k1 * x**2 + k2 * y**2) / 2)
    modes = normal_modes(linearize(s, {x: 0, y: 0}, params={}))
    s0, v0 = np.array([0.1, -0.05]), np.array([0.2, 0.3])
    sol = s.simulate(3.0, {x: s0[0], y: s0[1], x.diff(t): v0[0], y.diff(t): v0[1]}, {}, rtol=1e-12, atol=1e-14,
                     t_eval=[1.0, 3.0])
    assert modes.motion(s0, v0, [1.0, 3.0]) == pytest.approx(sol.y[:, :2], abs=1e-9)
    with pytest.raises(AnalysisError, match="gyroscopic"):
        modes.fit(s0, v0)
    with pytest.raises(AnalysisError, match="gyroscopic"):
        modes.normal_coordinates(s0)
    assert "mode" in modes_html(modes)


def test_damped_refused_with_pointer_to_roots_and_undamped_unchanged():
    x = coordinates("x")
    m, k, b = parameters("m k b")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-b * x.diff(t) ** 2 / 2)
    with pytest.raises(AnalysisError, match="characteristic_roots"):
        normal_modes(linearize(s), {"m": 1, "k": 4, "b": 0.4})
    with pytest.raises(AnalysisError, match="b = 0"):
        linearize(s).frequency_equation()
    undamped = normal_modes(linearize(s), {"m": 1, "k": 4, "b": 0})  # b = 0 exactly: the real modes as before
    assert undamped.kind == "undamped" and undamped.omega == pytest.approx([2.0], rel=1e-14)
    sym = linearize(System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2))
    w = sp.Symbol("omega", positive=True)
    assert sp.expand(sym.frequency_equation(w) - (m * w**2 - k)) == 0  # b = 0: the frequency equation stays


def test_cli_modes_prints_frequencies_from_the_roots(tmp_path):
    spec = tmp_path / "cone.py"
    spec.write_text(textwrap.dedent('''
        import sympy as sp
        from lagrange import Particle, System, coordinates, parameters
        th, ph = coordinates("theta phi")
        m, g, l = parameters("m g l")
        pos = (l * sp.sin(th) * sp.cos(ph), l * sp.sin(th) * sp.sin(ph), -l * sp.cos(th))
        system = System([th, ph], bodies=[Particle(m, pos)], V=m * g * pos[2], name="spherical pendulum")
        params = {"m": 0.7, "g": 9.81, "l": 1.3}
    '''))
    th0 = 0.6
    w = np.sqrt(G / (L * np.cos(th0)))
    out = subprocess.run([sys.executable, "-m", "lagrange.cli", "modes", str(spec), "--about", f"theta={th0}",
                          "--about", f"phi_dot={float(w)!r}", "--json"], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    report = json.loads(out.stdout)
    omega = conical_closed_form(th0)
    freq = [m["frequency"] for m in report["modes"]]
    assert report["kind"] == "steady motion" and report["stable"]
    assert freq == pytest.approx([0.0, 0.0, omega], rel=1e-7, abs=1e-12)  # φ ignorable: a double root 0
    assert report["modes"][-1]["period"] == pytest.approx(2 * np.pi / omega, rel=1e-7)
    assert report["modes"][-1]["eigenvalue"] == pytest.approx([0.0, omega], rel=1e-7, abs=1e-12)


@pytest.mark.parametrize("root", [1, -1], ids=["slow precession", "fast precession"])
def test_heavy_top_nutation_about_steady_precession_agrees_with_routhian(root):
    """Heavy symmetric top (Wells Ex. 11.2) in steady precession Ω at θ0 with spin n: the full 3-coordinate
    linearization has a gyroscopic b; its nutation frequency equals the Routhian's (ψ, φ reduced out: a 1-D
    oscillation in θ) and the closed form ω² = ((I3 n − 2 I1 Ω cos θ0)/I1)² + Ω² sin²θ0."""
    from lagrange import EulerAngles, RigidBody

    psi, th, ph = coordinates("psi theta phi")
    M, g, l, I1, I3 = parameters("M g l I1 I3")
    top = RigidBody(M, (I1, I1, I3), orientation=EulerAngles(psi, th, ph), com=(0, 0, l))
    s = System([psi, th, ph], bodies=[top], V=M * g * top.centre_of_mass[2])
    vals = {"M": 1.0, "g": 9.81, "l": 0.2, "I1": 0.05, "I3": 0.02}
    th0, n = 0.5, 40.0
    # the two precession rates: M g l = Ω (I3 n − I1 Ω cos θ0)
    a_, b_, c_ = -0.05 * np.cos(th0), 0.02 * n, -1.962
    w = (-b_ + root * np.sqrt(b_**2 - 4 * a_ * c_)) / (2 * a_)
    lin = linearize(s, {psi: 0, th: th0, ph: 0}, velocities={psi.diff(t): w, ph.diff(t): n - w * np.cos(th0)},
                    params=vals)
    modes = normal_modes(lin)
    assert modes.kind == "gyroscopic"
    R = routhian(s)
    mom = {p.name: p for p in R.momenta}
    pphi = 0.02 * n
    ppsi = 0.05 * w * np.sin(th0) ** 2 + pphi * np.cos(th0)
    red = oscillations_about_steady_motion(R, {th: th0})
    subs = {sym: vals[sym.name] for sym in s.parameters} | {mom["p_phi"]: pphi, mom["p_psi"]: ppsi}
    nutation = np.sqrt(float(red.c[0, 0].subs(subs)) / float(red.a[0, 0].subs(subs)))
    assert modes.omega[-1] == pytest.approx(nutation, rel=1e-8)
    assert modes.omega[:-1] == pytest.approx([0.0, 0.0], abs=1e-9)  # ψ and φ: free
    closed = np.sqrt(((0.02 * n - 2 * 0.05 * w * np.cos(th0)) / 0.05) ** 2 + w**2 * np.sin(th0) ** 2)
    assert modes.omega[-1] == pytest.approx(closed, rel=1e-9)
