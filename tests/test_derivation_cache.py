"""The derivation cache (lagrange.codegen.derivation_cache): a re-run in a fresh process loads the derived
equations and the generated source instead of deriving and generating; any declared change, any version
change and any damage gives a miss and a rebuild with the right answer; turned off, nothing is written.

``DERIVATION_CACHE_SCENARIOS`` counts the scenarios tested here (docs/guarantees.md cites it).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import platform
import subprocess
import sys
import textwrap

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.codegen import cse as cse_module
from lagrange.codegen import derivation_cache as dc
from lagrange.codegen import numeric
from lagrange.derive import lagrange as derive_module
from lagrange.simplification import is_zero

#: how a cache entry is damaged; each must be detected and the entry rebuilt
DAMAGES = ("truncated", "garbage", "empty", "payload_bit_flip", "unpicklable_payload", "other_environment",
           "other_key")
#: targets whose version is in the key
VERSIONS = ("lagrange", "sympy", "python", "machine", "lagrange_source")
#: declared changes that must change the key (see _variants)
CHANGES = ("mass", "V_term", "constraint", "constraint_kind", "P", "rayleigh", "force", "prescribed", "parameters",
           "name", "coordinate_order", "coordinate_assumptions")
#: changes also run end to end (a miss, a new entry, the right answer)
END_TO_END = ("mass", "V_term", "constraint")
#: spellings of LAGRANGE_DERIVATION_CACHE that turn the cache off
OFF_VALUES = ("0", "off", "False", " no ")
#: fresh-process hit, in-process reload, every System attribute keyed, equal declarations share a key, CHANGES,
#: END_TO_END, DAMAGES on each of the two kinds of entry, VERSIONS, OFF_VALUES, a user sympy class is not cached,
#: source entries are content-addressed, and T from bodies: keyed by every field it is built from, T itself
#: outside them, loaded without building T; entries rebuilt unevaluated and identical
DERIVATION_CACHE_SCENARIOS = (1 + 1 + 1 + 1 + len(CHANGES) + len(END_TO_END) + 2 * len(DAMAGES) + len(VERSIONS)
                              + len(OFF_VALUES) + 1 + 1 + 3 + 1)

Y = np.array([0.3, -0.2, 0.1, 0.4])


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """An empty cache directory, the derivation cache on, and call counters on derivation and CSE."""
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv(dc.ENV_VAR, "1")
    calls = {"derive": 0, "fuse": 0}
    real_derive, real_fuse = derive_module.lagrange_equations, cse_module.fuse

    def derive(system):
        calls["derive"] += 1
        return real_derive(system)

    def fuse(*args, **kwargs):
        calls["fuse"] += 1
        return real_fuse(*args, **kwargs)

    monkeypatch.setattr(derive_module, "lagrange_equations", derive)
    monkeypatch.setattr(cse_module, "fuse", fuse)  # code generation imports it when it runs
    return tmp_path, calls


def _declare(mass: float = 1, *, v_extra=0, constraint=None, name: str = "") -> lg.System:
    """A planar pendulum in Cartesian coordinates with a rod constraint (x² + y² = l²)."""
    x, y = lg.coordinates("x y")
    m, g, l = lg.parameters("m g l")
    rod = x**2 + y**2 - l**2 if constraint is None else constraint(x, y, l)
    return lg.System([x, y], bodies=[lg.Particle(mass * m, (x, y))], V=m * g * y + v_extra * y**2,
                     constraints=[rod], name=name)


def _variants() -> dict:
    x, y = lg.coordinates("x y")
    m, g, l, c, k = lg.parameters("m g l c k")
    xd, yd = x.diff(t), y.diff(t)

    def system(coords=(x, y), T=m * (xd**2 + yd**2) / 2, **kw):
        kw.setdefault("V", m * g * y)
        kw.setdefault("constraints", [x**2 + y**2 - l**2])
        return lg.System(list(coords), T=T, **kw)

    s = lg.coordinates("s")
    xr = sp.Function("x")(t)  # not real: only the function's assumptions differ from x
    return {
        "base": system(),
        "mass": system(T=2 * m * (xd**2 + yd**2) / 2),
        "V_term": system(V=m * g * y + k * x**2 / 2),
        "constraint": system(constraints=[x**2 + y**2 - 2 * l**2]),
        "constraint_kind": system(constraints=[lg.Holonomic(x**2 + y**2 - l**2, unilateral=True)]),
        "P": system(P=-c * xd**2 / 2),
        "rayleigh": system(rayleigh=c * xd**2 / 2),
        "force": system(forces={x: k}),
        "prescribed": system(V=m * g * y + k * x * s, prescribed={s: sp.sin(t)}),
        "parameters": system(parameters=[m, g, l, k]),
        "name": system(name="pendulum"),
        "coordinate_order": system(coords=(y, x)),
        "coordinate_assumptions": lg.System([xr, y], T=m * (xr.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=m * g * y,
                                            constraints=[xr**2 + y**2 - l**2]),
    }


def _entries(root, kind: str = "") -> list:
    return sorted(root.glob(f"{kind}*_*.pkl")) + sorted(root.glob(f"{kind}*_*.txt"))


def _digest(eqs) -> str:
    """The equations' printed form, hashed: the printer orders terms and factors canonically, so two
    derivations of the same equations agree even when sympy's cache stored their arguments in another order
    (srepr prints the stored order, which made this test depend on what ran before it in the process)."""
    return hashlib.sha256(str(tuple(getattr(eqs, f.name) for f in dataclasses.fields(eqs))).encode()).hexdigest()


_CHILD = textwrap.dedent("""
    import hashlib, json, sys, dataclasses
    import numpy as np, sympy as sp
    import lagrange as lg
    from lagrange.examples import n_link_pendulum
    if sys.argv[1] == "warm":  # derivation and CSE must not run at all: fail loudly if they do
        import lagrange.codegen.cse as cse_module
        import lagrange.derive.lagrange as derive_module
        def forbidden(*args, **kwargs):
            raise AssertionError("derived or generated again")
        derive_module.lagrange_equations = cse_module.fuse = forbidden
    x, y = lg.coordinates("x y")
    m, g, l = lg.parameters("m g l")
    rod = lg.System([x, y], bodies=[lg.Particle(m, (x, y))], V=m * g * y, constraints=[x**2 + y**2 - l**2])
    out = {}
    for label, system, params, initial in (
            ("double", n_link_pendulum(2), {"g": 9.81}, {"q1": 0.6, "q2": -0.3, "q1_dot": 0, "q2_dot": 0}),
            ("rod", rod, {"m": 1, "g": 9.81, "l": 1}, {"x": 0.6, "y": -0.8, "x_dot": 0.8, "y_dot": 0.6})):
        eqs = system.derived
        fields = tuple(getattr(eqs, f.name) for f in dataclasses.fields(eqs))
        out[label + " equations"] = hashlib.sha256(sp.srepr(fields).encode()).hexdigest()
        for backend in ("python", "numba") if sys.argv[2] == "1" else ("python",):
            model = system.compile(params, backend=backend)
            traj = system.simulate(1.0, initial, params, backend=backend, loop="scipy", rtol=1e-10, atol=1e-12)
            out[f"{label} {backend} source"] = model.source
            out[f"{label} {backend} final"] = traj.y[-1].tolist()
    print(json.dumps(out))
""")


def _run_child(cache_dir, phase: str, seed: str) -> dict:
    numba = "1" if _has_numba() else "0"
    env = dict(os.environ, LAGRANGE_CACHE_DIR=str(cache_dir), PYTHONHASHSEED=seed)
    env.pop(dc.ENV_VAR, None)  # the default: on
    r = subprocess.run([sys.executable, "-c", _CHILD, phase, numba], env=env, capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr[-3000:]
    return json.loads(r.stdout.strip().splitlines()[-1])


def _has_numba() -> bool:
    import importlib.util

    return importlib.util.find_spec("numba") is not None


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_hit_in_fresh_process_is_identical(tmp_path, monkeypatch):
    """A second fresh interpreter (other hash seed) with derivation and CSE disabled by force gets the same
    equations (srepr), the same source and the same simulation, bit for bit; it writes no entry. Both agree
    with a run that has the cache off."""
    cold = _run_child(tmp_path, "cold", "1")
    written = {p: p.stat().st_mtime_ns for p in _entries(tmp_path)}
    assert len([p for p in written if p.name.startswith("derived_")]) == 2
    # the right-hand side's source per backend, and each equations' diagnostics source (the verdict's energy)
    assert len([p for p in written if p.name.startswith("source_")]) == (6 if _has_numba() else 4)
    warm = _run_child(tmp_path, "warm", "2")
    assert warm == cold
    assert {p: p.stat().st_mtime_ns for p in _entries(tmp_path)} == written  # nothing rewritten
    # against an independent derivation in this process with the cache off (CSE may order terms differently)
    monkeypatch.setenv(dc.ENV_VAR, "0")
    traj = _declare().simulate(1.0, {"x": 0.6, "y": -0.8, "x_dot": 0.8, "y_dot": 0.6}, {"m": 1, "g": 9.81, "l": 1},
                               rtol=1e-10, atol=1e-12)
    assert np.allclose(traj.y[-1], cold["rod python final"], rtol=1e-8, atol=1e-9)
    assert abs(np.hypot(*cold["rod python final"][:2]) - 1.0) < 1e-8  # stays on the rod


def test_second_build_loads_and_matches(cache):
    root, calls = cache
    first = _declare().derived
    model = _declare().compile({"m": 1, "g": 9.81, "l": 1})
    assert calls == {"derive": 1, "fuse": 1}
    again = _declare()  # a new System object: its memo is empty, the disk entry is used
    eqs = again.derived
    model2 = again.compile({"m": 1, "g": 9.81, "l": 1})
    assert calls == {"derive": 1, "fuse": 1}
    assert _digest(eqs) == _digest(first) and model2.source == model.source
    ref = _declare().compile({"m": 1, "g": 9.81, "l": 1}, backend="reference")
    assert np.allclose(model2.fun(0.0, Y), ref.fun(0.0, Y), rtol=1e-12, atol=1e-12)


def test_every_system_attribute_is_keyed_or_explained():
    """A new System attribute must enter the key or be listed as irrelevant to the derivation."""
    s = _declare()
    s.T  # noqa: B018 - a cached property: built on first access when the bodies pin it down
    keyed = {name for name, _ in dc._declaration(s)}
    assert set(vars(s)) - {"_frozen"} == keyed | set(dc.UNKEYED_ATTRIBUTES)
    assert not keyed & set(dc.UNKEYED_ATTRIBUTES)


def test_equal_declarations_share_a_key():
    assert dc.declaration_key(_declare()) == dc.declaration_key(_declare())
    assert dc.declaration_key(_variants()["base"]) == dc.declaration_key(_variants()["base"])


def test_every_declared_change_changes_the_key():
    variants = _variants()
    assert set(variants) == {"base", *CHANGES}
    keys = {label: dc.declaration_key(s) for label, s in variants.items()}
    assert None not in keys.values()
    assert len(set(keys.values())) == len(keys), "two different declarations share a key"


@pytest.mark.parametrize("change", END_TO_END)
def test_changed_declaration_misses_and_is_right(cache, change):
    """End to end: after the base system is cached, a changed mass, V term or constraint derives anew (a new
    entry) and its right-hand side matches the reference backend of the changed system."""
    root, calls = cache
    _declare().compile({"m": 1, "g": 9.81, "l": 1})
    build = {"mass": lambda: _declare(mass=2), "V_term": lambda: _declare(v_extra=3),
             "constraint": lambda: _declare(constraint=lambda x, y, l: x**2 + 2 * y**2 - l**2)}[change]
    model = build().compile({"m": 1, "g": 9.81, "l": 1})
    assert calls == {"derive": 2, "fuse": 2}
    assert len(_entries(root, "derived")) == 2
    ref = build().compile({"m": 1, "g": 9.81, "l": 1}, backend="reference")
    base = _declare().compile({"m": 1, "g": 9.81, "l": 1}, backend="reference")
    assert np.allclose(model.fun(0.0, Y), ref.fun(0.0, Y), rtol=1e-12, atol=1e-12)
    assert not np.allclose(model.fun(0.0, Y), base.fun(0.0, Y))


def _damage(path, how: str) -> None:
    """Damage the entry at ``path``: raw damage fails authentication (lagrange.codegen.cache); the last three
    kinds are written *sealed*, as lagrange itself would write them, and must fail the header check."""
    from lagrange.codegen.cache import read_verified, write_sealed

    data = path.read_bytes()
    head, _, payload = read_verified(path).partition(b"\n")
    key = path.stem.split("_", 1)[1]
    if how == "truncated":
        path.write_bytes(data[: len(data) * 2 // 3])
    elif how == "garbage":
        path.write_bytes(b"\x80garbage\n" * 9)
    elif how == "empty":
        path.write_bytes(b"")
    elif how == "payload_bit_flip":
        path.write_bytes(data[:-5] + bytes([data[-5] ^ 1]) + data[-4:])
    elif how == "unpicklable_payload":  # a header that matches its payload, which is not what was stored
        bad = b"\x80\x05not a pickle" if path.suffix == ".pkl" else b"\xff\xfe not utf-8"
        write_sealed(path, dc._header(key, bad) + b"\n" + bad)
    elif how == "other_environment":  # a well-formed entry written by other versions
        write_sealed(path, head.replace(b"sympy ", b"sympy 0.0.1+") + b"\n" + payload)
    else:  # a well-formed entry of another key, sealed under this entry's name
        other = "0" * len(key)
        write_sealed(path, dc._header(other, payload) + b"\n" + payload)


@pytest.mark.parametrize("kind", ["derived", "source"])
@pytest.mark.parametrize("how", DAMAGES)
def test_damaged_entry_is_rebuilt(cache, kind, how):
    root, calls = cache
    model = _declare().compile({"m": 1, "g": 9.81, "l": 1})
    digest = _digest(_declare().derived)
    (entry,) = _entries(root, kind)
    intact = entry.read_bytes()
    _damage(entry, how)
    assert entry.read_bytes() != intact
    system = _declare()
    again = system.compile({"m": 1, "g": 9.81, "l": 1})
    assert calls == ({"derive": 2, "fuse": 1} if kind == "derived" else {"derive": 1, "fuse": 2})
    assert _digest(system.derived) == digest and again.source == model.source
    assert np.array_equal(again.fun(0.0, Y), model.fun(0.0, Y))
    assert dc._read(entry, entry.stem.split("_", 1)[1]) is not None  # rewritten, intact
    assert not list(root.glob(".*.tmp"))


def _bump(monkeypatch, target: str) -> None:
    if target == "lagrange":
        monkeypatch.setattr(lg, "__version__", lg.__version__ + ".post1")
    elif target == "sympy":
        monkeypatch.setattr(sp, "__version__", sp.__version__ + ".post1")
    elif target == "python":
        monkeypatch.setattr(sys, "version", sys.version + " (upgraded)")
    elif target == "machine":
        monkeypatch.setattr(platform, "machine", lambda: "other-machine")
    else:  # an edited checkout: the derive/codegen source hash changes
        monkeypatch.setattr(dc, "_source_digest", lambda: "f" * 64)


@pytest.mark.parametrize("target", VERSIONS)
def test_version_change_gives_new_entries(cache, monkeypatch, target):
    root, calls = cache
    system = _declare()
    key, env = dc.declaration_key(system), dc.environment()
    system.compile({"m": 1, "g": 9.81, "l": 1})
    old = _entries(root)
    with monkeypatch.context() as m:
        _bump(m, target)
        assert dc.declaration_key(system) != key and dc.environment() != env
        _declare().compile({"m": 1, "g": 9.81, "l": 1})
        assert calls == {"derive": 2, "fuse": 2}  # the old entries are not used
        assert len(_entries(root)) == 2 * len(old)
    _declare().compile({"m": 1, "g": 9.81, "l": 1})  # back to the current versions: the first entries hit
    assert calls == {"derive": 2, "fuse": 2}


@pytest.mark.parametrize("value", OFF_VALUES)
def test_turned_off_writes_and_reads_nothing(cache, monkeypatch, value):
    root, calls = cache
    _declare().compile({"m": 1, "g": 9.81, "l": 1})  # an entry exists...
    before = {p: p.stat().st_mtime_ns for p in _entries(root)}
    monkeypatch.setenv(dc.ENV_VAR, value)
    assert not dc.enabled()
    for _ in range(2):
        _declare().compile({"m": 1, "g": 9.81, "l": 1})
    assert calls == {"derive": 3, "fuse": 3}  # ...and is not read
    assert {p: p.stat().st_mtime_ns for p in _entries(root)} == before
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(root / "empty"))
    _declare().compile({"m": 1, "g": 9.81, "l": 1})
    assert not _entries(root / "empty")


class softplus(sp.Function):  # noqa: N801 - a user's sympy function: its srepr does not say what it does
    def fdiff(self, argindex=1):
        return 1 / (1 + sp.exp(-self.args[0]))


def test_user_sympy_class_is_not_cached(cache):
    """Its srepr names the class but not its behaviour (a same-named class elsewhere may differ)."""
    root, calls = cache
    x = lg.coordinates("x")
    m, k = lg.parameters("m k")
    system = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * softplus(x))
    assert dc.declaration_key(system) is None
    eqs = system.derived
    assert calls["derive"] == 1 and not _entries(root)
    expected = -k / (1 + sp.exp(-eqs.q[0]))
    assert is_zero(eqs.forcing[0] - expected)


def test_source_entries_are_content_addressed(cache):
    """Equations built another way (here: the derived ones with a changed forcing) get their own source
    entry, and a Baumgarte constraint right-hand side its own; each model matches its reference."""
    root, calls = cache
    system = _declare()
    eqs = system.derived
    params = {"m": 1, "g": 9.81, "l": 1}
    plain = numeric.compile_equations(eqs, params)
    g = eqs.parameters[0]
    pushed = dataclasses.replace(eqs, forcing=eqs.forcing + sp.ImmutableMatrix([g, 0]))
    other = numeric.compile_equations(pushed, params)
    from lagrange.integrate.constrained import baumgarte_rhs

    stabilised = numeric.compile_equations(eqs, params, constraint_rhs=baumgarte_rhs(eqs, 10.0, 10.0))
    assert calls["fuse"] == 3 and len(_entries(root, "source")) == 3
    ref = numeric.compile_equations(pushed, params, backend="reference")
    assert np.allclose(other.fun(0.0, Y), ref.fun(0.0, Y), rtol=1e-12, atol=1e-12)
    assert not np.allclose(other.fun(0.0, Y), plain.fun(0.0, Y))
    assert stabilised.source != plain.source
    numeric.compile_equations(pushed, params)  # the same content again: a hit
    assert calls["fuse"] == 3


def test_cache_is_pruned_to_its_limit_oldest_first(cache, monkeypatch):
    """Stranded entries (older sources, other declarations) do not accumulate: a write beyond the limit
    deletes the least recently written entries, down to 90 % of the limit; files that are not entries stay."""
    root, calls = cache
    for i in range(12):
        path = root / f"derived_{i:064x}.pkl"
        path.write_bytes(b"old entry")
        os.utime(path, (1_000_000 + i, 1_000_000 + i))
    (root / "model_abc.py").write_text("# a generated module, not an entry\n")
    monkeypatch.setenv(dc.MAX_ENTRIES_VAR, "10")
    system = _declare()
    assert system.derived is not None  # a miss: writes one entry and prunes 13 -> 9
    names = {p.name for p in _entries(root)}
    assert len(names) == 9
    assert not any(f"derived_{i:064x}.pkl" in names for i in range(4))  # the four oldest went
    assert f"derived_{11:064x}.pkl" in names and (root / "model_abc.py").exists()
    assert _declare().derived == system.derived and calls["derive"] == 1  # the new entry survived: a hit
    assert dc.prune(root, 100) == 0


def _near_misses() -> list[tuple[object, object]]:
    """Pairs of different declarations' pieces that a careless content hash could conflate."""
    a, b, x = sp.symbols("a b x")
    f = sp.Function("f")
    return [
        (x, 1.0 * x), (sp.Float("0.1", 15), sp.Float("0.1", 30)), (sp.Rational(1, 2), sp.Float(0.5)),
        (sp.Symbol("a", positive=True), a), (sp.Function("f", real=True)(t), f(t)), (a - b, b - a),
        (sp.sin(a), sp.cos(a)), (sp.Dummy("a"), sp.Dummy("a")), (("ab", "c"), ("a", "bc")),
        (((a, b), x), (a, (b, x))), ([a], (a,)), (1, 1.0), (1, True), (None, "None"), ({"k": 1}, {"k": 1.0}),
        (f(t).diff(t), f(t).diff(t, 2)),
        (sp.Matrix([[a, b]]), sp.ImmutableMatrix([[a, b]])), (sp.ImmutableMatrix([[a, b]]), sp.ImmutableMatrix([a, b])),
    ]


def test_hash_tree_separates_near_misses_and_ignores_sharing():
    """The key's hash tree (dc._KeyHasher) gives different digests to different content — the near misses above,
    and every pair of the declaration variants of test_every_declared_change_changes_the_key, compared with
    their printed srepr as the independent truth — and equal digests to equal content built twice (sympy's
    cache cleared in between, so no object is shared) or rebuilt node by node."""
    for left, right in _near_misses():
        assert dc._fingerprint(left) != dc._fingerprint(right), (left, right)
    x = sp.Symbol("x")  # a Poly's domain is not in its srepr: Poly(x**2, x) and over QQ print alike
    assert sp.srepr(sp.Poly(x**2, x)) == sp.srepr(sp.Poly(x**2, x, domain="QQ"))
    assert dc._fingerprint(sp.Poly(x**2, x)) is None and dc._fingerprint((x, sp.Poly(x**2, x, domain="QQ"))) is None
    variants = _variants()
    texts = {label: dc._text(dc._declaration(s)) for label, s in variants.items()}
    digests = {label: dc._fingerprint(dc._declaration(s)) for label, s in variants.items()}
    for one in variants:
        for other in variants:
            assert (texts[one] == texts[other]) == (digests[one] == digests[other]), (one, other)

    from sympy.core.cache import clear_cache

    from lagrange.examples import n_link_pendulum

    first = n_link_pendulum(3, symbolic=True)
    first.T  # noqa: B018 - built now (on first access), before the cache is cleared
    clear_cache()
    second = n_link_pendulum(3, symbolic=True)
    assert first.T is not second.T and dc._fingerprint(first.T) == dc._fingerprint(second.T)

    def rebuild(e):
        return e.func(*[rebuild(arg) for arg in e.args]) if e.args else e

    assert dc._fingerprint(rebuild(first.T)) == dc._fingerprint(first.T)
    assert dc.declaration_key(first) == dc.declaration_key(second)


def _body_variants() -> dict:
    """Declarations whose T comes from bodies: each differs from "base" in one field the key reads."""
    a, b, s = lg.coordinates("a b s")
    m, l, I1, I3 = lg.parameters("m l I1 I3")
    euler = lg.EulerAngles(a, b, sp.S.Zero)
    sequence = lg.RotationSequence(("z", a), ("x", b))

    def system(*bodies, **kw):
        kw.setdefault("V", m * l * sp.cos(b))
        return lg.System([a, b], bodies=list(bodies), **kw)

    def rigid(mass=m, inertia=(I1, I1, I3), origin=(0, 0, 0), orientation=euler, com=(0, 0, l)):
        return lg.RigidBody(mass, inertia, origin=origin, orientation=orientation, com=com)

    bob = lg.Particle(m, (l * sp.sin(a), -l * sp.cos(a)))
    return {
        "base": system(rigid(), bob),
        "particle mass": system(rigid(), lg.Particle(2 * m, (l * sp.sin(a), -l * sp.cos(a)))),
        "particle position": system(rigid(), lg.Particle(m, (l * sp.sin(a), -l * sp.cos(a), l))),
        "body order": system(bob, rigid()),
        "rigid mass": system(rigid(mass=2 * m), bob),
        "inertia": system(rigid(inertia=(I1, I3, I3)), bob),
        "origin": system(rigid(origin=(l * a, 0, 0)), bob),
        "com": system(rigid(com=(0, l, 0)), bob),
        # the same rotation declared three ways: ω is built differently (Wells 8.11, the sequence, vee(RᵀṘ))
        "orientation matrix": system(rigid(orientation=euler.matrix), bob),
        "sequence": system(rigid(orientation=sequence), bob),
        "prescribed": lg.System([a, b], bodies=[rigid(origin=(s, 0, 0)), bob], V=m * l * sp.cos(b),
                                prescribed={s: sp.sin(lg.t)}),
        "prescribed otherwise": lg.System([a, b], bodies=[rigid(origin=(s, 0, 0)), bob], V=m * l * sp.cos(b),
                                          prescribed={s: sp.cos(lg.t)}),
    }


def test_bodies_key_t_by_every_field_it_is_built_from():
    """T from Particles and RigidBodies is keyed by the bodies' fields (not built): every field T reads moves
    the key, equal declarations share it, and the T built later is the eager one's."""
    variants = _body_variants()
    assert all(s._T_declaration is not None and "T" not in vars(s) for s in variants.values())
    keys = {label: dc.declaration_key(s) for label, s in variants.items()}
    assert len(set(keys.values())) == len(keys), keys
    assert all("T" not in vars(s) for s in variants.values())  # the key did not build T
    again = _body_variants()
    assert {label: dc.declaration_key(s) for label, s in again.items()} == keys
    # the z-x sequence's matrix is z-x-z Euler angles' with φ = 0: the same R, the same T, the same key
    a, b = again["base"].coordinates
    m, l, I1, I3 = lg.parameters("m l I1 I3")
    same_R = lg.System([a, b], bodies=[lg.RigidBody(m, (I1, I1, I3), orientation=lg.RotationSequence(
        ("z", a), ("x", b)).matrix, com=(0, 0, l)), again["base"].bodies[1]], V=m * l * sp.cos(b))
    assert dc.declaration_key(same_R) == keys["orientation matrix"]
    # a T given directly, equal to the bodies' T, is keyed by T: another key, and the same T as the lazy one
    base = variants["base"]
    given = lg.System(list(base.coordinates), T=base.T, V=base.V)
    assert given._T_declaration is None and dc.declaration_key(given) != keys["base"]
    # the lazy T with a prescribed motion is the eager one: T of the bodies, then the motion substituted
    a, b, s = lg.coordinates("a b s")
    body = variants["prescribed"].bodies[0]
    eager = (body.kinetic_energy() + variants["prescribed"].bodies[1].kinetic_energy()).subs(s, sp.sin(lg.t)).doit()
    assert sp.simplify(variants["prescribed"].T - eager) == 0


def test_bodies_key_outside_what_pins_t_down():
    """A Quaternion orientation, a varying mass or a body of another class: T is built at declaration and
    keys the entry itself."""
    a, b, c, d = lg.coordinates("a b c d")
    m, I1 = lg.parameters("m I1")
    quaternion = lg.System([a, b, c, d], bodies=[lg.RigidBody(m, (I1, I1, I1), orientation=lg.Quaternion(a, b, c, d))])

    class Bob(lg.Particle):
        pass

    subclass = lg.System([a], bodies=[Bob(m, (sp.sin(a), sp.cos(a)))])
    varying = lg.System([a], bodies=[lg.Particle(m * (1 + a**2), (a,))])
    for s in (quaternion, subclass, varying):
        assert s._T_declaration is None and "T" in vars(s)
        assert dc.declaration_key(s) is not None


def test_bodies_key_loads_without_building_t(cache):
    """A second System of a body declaration loads its equations from the entry without building T, and
    they are the ones derived (rigid body, particle, prescribed motion)."""
    root, calls = cache
    first = _body_variants()["prescribed"]
    eqs = first.derived
    again = _body_variants()["prescribed"]
    loaded = again.derived
    assert calls["derive"] == 1 and "T" not in vars(again)
    assert _digest(loaded) == _digest(eqs)
    fresh = _body_variants()["prescribed"]
    assert sp.simplify(fresh.T - first.T) == 0  # (built on access, from the same fields)


def test_entry_pickling_rebuilds_nodes_unevaluated_and_identical():
    """Add, Mul, Pow and sympy's functions are stored as their arguments and rebuilt without evaluation (and
    without deducing commutativity again): every node comes back with the same srepr, equal, with the same hash
    and assumptions — for functions whose eval would act (multiples of π, parities, signs) and a
    non-commutative product."""
    import pickle

    x, y = lg.coordinates("x y")
    a = sp.Symbol("a", positive=True)
    A, B = sp.symbols("A B", commutative=False)
    exprs = [
        sp.sin(x - y) * sp.cos(2 * x) + sp.exp(-a * x) * sp.sqrt(1 + y**2),
        sp.Abs(x - y) + sp.sign(x.diff(lg.t)) * a + sp.atan2(y, x),
        sp.Piecewise((x, x > 0), (-x, True)) + sp.Heaviside(y - 1) + sp.besselj(1, a * x),
        sp.cos(sp.pi / 3 + x) ** 2 + sp.tan(-x) + sp.log(a * y**2),
        A * B - B * A + 2 * A * x,
    ]
    for e in exprs:
        back = pickle.loads(dc._dumps(e))  # noqa: S301 - the test's own bytes
        assert sp.srepr(back) == sp.srepr(e) and back == e and hash(back) == hash(e)
        assert back.is_commutative == e.is_commutative
        assert [n.is_commutative for n in sp.preorder_traversal(back)] == [
            n.is_commutative for n in sp.preorder_traversal(e)]


def _source_tree(root) -> None:
    for rel in ("conventions.py", "simplification.py", "symengine_bridge.py", "model/a.py", "derive/b.py",
                "codegen/c.py", "codegen/sub/d.py", "model/notes.txt"):
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(f"# {rel}\nx = 1\n")


def test_source_digest_is_remembered_by_file_identity_and_follows_every_edit(cache, tmp_path, monkeypatch):
    """The digest of the source files is read from its sealed memo while no file changed (same size, inode,
    modification and change times), and computed again from the bytes after an edit that keeps the size and
    even restores the modification time; a damaged memo is refused and rewritten; with the cache off no memo
    is written or read."""
    root, _ = cache
    src = tmp_path / "src"
    _source_tree(src)
    content = dc._content_digest(str(src), dc._source_files(str(src)))
    assert dc._source_files(str(src))[-1] == "codegen/sub/d.py" and "model/notes.txt" not in dc._source_files(str(src))
    assert dc.sources_digest(str(src)) == content
    (memo,) = root.glob("srcdigest_*.txt")

    def no_read(*args):
        raise AssertionError("the files were read although none changed")

    with monkeypatch.context() as m:
        m.setattr(dc, "_content_digest", no_read)
        assert dc.sources_digest(str(src)) == content  # from the memo

    edited = src / "derive" / "b.py"
    before = edited.stat()
    edited.write_text(edited.read_text().replace("x = 1", "x = 2"))  # same size
    os.utime(edited, ns=(before.st_atime_ns, before.st_mtime_ns))  # and the same modification time
    new = dc.sources_digest(str(src))
    assert new != content and new == dc._content_digest(str(src), dc._source_files(str(src)))
    assert len(list(root.glob("srcdigest_*.txt"))) == 2

    (current,) = set(root.glob("srcdigest_*.txt")) - {memo}
    current.write_bytes(current.read_bytes().replace(new.encode(), b"0" * 64))  # a forged digest, no new seal
    monkeypatch.setattr("lagrange.codegen.cache._warned", False)  # (the warning is given once per process)
    with pytest.warns(lg.errors.CacheIntegrityWarning, match="authentication tag"):
        assert dc.sources_digest(str(src)) == new  # refused: the bytes are read again, the memo rewritten
    assert dc.sources_digest(str(src)) == new

    off = tmp_path / "off"
    _source_tree(off)
    monkeypatch.setenv(dc.ENV_VAR, "0")
    before = set(root.iterdir())
    assert dc.sources_digest(str(off)) == dc._content_digest(str(off), dc._source_files(str(off)))
    assert set(root.iterdir()) == before
