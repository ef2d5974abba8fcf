"""The earth as an ellipsoid (Wells ch. 14, eqs. 14.1–14.13, Table 14.1)."""

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import DeclarationError, Force, Particle, System, coordinates
from lagrange.model.frames import (
    OMEGA_EARTH,
    WELLS_1924,
    EarthFrame,
    Ellipsoid,
    apparent_gravity,
    true_gravity_magnitude,
)

DEG = [0, 30, 45, 60, 90]
# Wells Table 14.1 as printed (R − R1 at 45° corrected to 21 440 m, catalog ⚠; g within 5e-3 gal)
R1_BOOK = [6_378_388, 6_373_053, 6_367_695, 6_362_315, 6_356_912]
R_BOOK = [6_378_388, 6_383_755, 6_389_135, 6_394_529, 6_399_936]
GPRIME_BOOK = [978.049, 979.338, 980.629, 981.924, 983.221]
G_BOOK = [981.441, 981.883, 982.326, 982.773, 983.221]
ALPHA_MIN_BOOK = [0, 5.15, 5.95, 5.15, 0]
DPHI_SEC_BOOK = [0, 601.4463, 695.6609, 603.4782, 0]
R_MINUS_R1_BOOK = [0, 10_702, 21_440, 32_214, 43_024]
A_MINUS_R1_BOOK = [0, 5_335, 10_693, 16_073, 21_476]


def _phi(d):
    return sp.pi * d / 180


@pytest.mark.parametrize("i", range(5))
def test_table_14_1(i):
    E, Phi = WELLS_1924, _phi(DEG[i])
    R1, R = float(E.geocentric_radius(Phi)), float(E.radius(Phi))
    assert abs(R1 - R1_BOOK[i]) <= 1.0 and abs(R - R_BOOK[i]) <= 1.0
    assert abs((R - R1) - R_MINUS_R1_BOOK[i]) <= 10 and abs((float(E.a) - R1) - A_MINUS_R1_BOOK[i]) <= 1.0
    gp = float(apparent_gravity(Phi)) * 100  # gal
    assert abs(gp - GPRIME_BOOK[i]) <= 1e-3
    g, alpha = true_gravity_magnitude(Phi)
    assert abs(float(g) * 100 - G_BOOK[i]) <= 5e-3
    assert abs(float(alpha) * 180 / np.pi * 60 - ALPHA_MIN_BOOK[i]) <= 6e-3
    dphi = float(Phi - E.geocentric_latitude(Phi)) * 180 / np.pi * 3600
    assert abs(dphi - DPHI_SEC_BOOK[i]) <= 0.02 * max(1.0, DPHI_SEC_BOOK[i]) / 100 + 0.005


def test_series_14_2_14_5_14_7_against_the_closed_forms():
    """Wells' printed series agree with the exact ellipsoid formulas over all latitudes."""
    E = WELLS_1924
    for d in np.linspace(0, 90, 19):
        Phi = float(np.radians(d))
        s2, s22 = np.sin(Phi) ** 2, np.sin(2 * Phi) ** 2
        R1_series = 6378388 * (1 - 0.003367003 * s2 + 0.000007085 * s22)          # (14.2)
        R_series = 6378388 * (1 + 0.003378283 * s2 - 0.000004237 * s22)           # (14.5)
        dphi_series = 695.6635 * np.sin(2 * Phi) - 1.1731 * np.sin(4 * Phi) + 0.0026 * np.sin(6 * Phi)  # (14.7)
        assert abs(float(E.geocentric_radius(Phi)) - R1_series) < 1.0
        assert abs(float(E.radius(Phi)) - R_series) < 1.0
        Phi1 = float(E.geocentric_latitude(Phi))
        assert abs(np.degrees(Phi - Phi1) * 3600 - dphi_series) < 2e-3
        # (14.8): the same series in Φ1 with +1.1731 inverts it
        back = Phi1 + np.radians((695.6635 * np.sin(2 * Phi1) + 1.1731 * np.sin(4 * Phi1)
                                  + 0.0026 * np.sin(6 * Phi1)) / 3600)
        assert abs(np.degrees(back - Phi) * 3600) < 2e-3
        assert abs(float(E.geographic_latitude(Phi1)) - Phi) < 1e-13


def test_constants_and_height_correction():
    E = WELLS_1924
    assert abs(float(E.eccentricity_squared) - 0.00672267) < 1e-8
    assert abs(1 / float(E.flattening) - 297.0) < 0.01
    assert abs(float(OMEGA_EARTH) ** 2 * float(E.a) * 100 - 3.392) < 1e-3  # ω_e² a in gal
    Phi = _phi(45)
    g1000 = float(apparent_gravity(Phi, height=1000)) * 100
    assert abs(g1000 - (980.629 - (0.30855 - 0.000072) * 1)) < 1e-3  # (14.10) at h = 1 km


@pytest.mark.slow
def test_ellipsoidal_earth_frame_gives_wells_14_16_with_the_geographic_radius(agrees_with_wells_14_16):
    """A free particle in EarthFrame(Φ, ellipsoid=...) with true gravity: the equations are Wells' (14.16)
    (the R ω_e² terms cancel), the same as those of a sphere of radius R(Φ); the deflection of true gravity
    from the normal is α of (14.12)."""
    x, y, z = coordinates("x1 y1 z1")
    m, w, Phi = lg.parameters("m omega_e Phi")
    E = EarthFrame(Phi, omega=w, ellipsoid=WELLS_1924)
    p = Particle(m, E.point((x, y, z)))
    s = System([x, y, z], bodies=[p], forces=[Force(p, E.gravity_force(m))])
    gp = apparent_gravity(Phi)
    agrees_with_wells_14_16(s, (x, y, z), m, w, Phi, gp)
    g, alpha = true_gravity_magnitude(0.7, omega=7.29211e-5)
    tg = E.true_gravity().subs({w: 7.29211e-5, Phi: 0.7})
    assert abs(float(sp.sqrt(tg.dot(tg))) - float(g)) < 1e-12
    assert abs(float(sp.atan2(tg[1], -tg[2])) - float(alpha)) < 1e-15


def test_ellipsoidal_earth_frame_rejects_bad_combinations():
    with pytest.raises(DeclarationError, match="either radius= .* or ellipsoid="):
        EarthFrame(0.5, radius=6_371_000, ellipsoid=WELLS_1924)
    with pytest.raises(DeclarationError, match="g_apparent"):
        EarthFrame(0.5).true_gravity()
    with pytest.raises(DeclarationError, match="a ≥ b > 0"):
        Ellipsoid(6_000_000, 6_100_000)
    sphere = Ellipsoid(6_371_000, 6_371_000)
    assert sphere.radius(0.3) == sphere.geocentric_radius(0.3) == 6_371_000
    assert lg.Ellipsoid is Ellipsoid
