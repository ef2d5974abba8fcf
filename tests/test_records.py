"""``@record`` (lagrange/records.py) behaves as ``@dataclass`` with the same options: each case declares one class
body twice — once with each decorator — and compares the two on everything a caller can observe."""

import copy
import dataclasses
import inspect
import pathlib
import pickle
import re
import sys
import types
from dataclasses import FrozenInstanceError, field

import pytest

from lagrange.records import record

OPTIONS = [{}, {"frozen": True}, {"eq": False}, {"frozen": True, "eq": False}, {"repr": False},
           {"slots": True}, {"frozen": True, "slots": True}]


def _module():
    """A module the twin classes live in (pickle finds classes by module and qualified name)."""
    mod = types.ModuleType("_record_twins")
    sys.modules[mod.__name__] = mod
    return mod


def _declare(decorator, name, options, docstring=True, post_init=False):
    def body(ns):
        ns["__annotations__"] = {"a": "int", "b": "str", "c": "list", "d": "int", "e": "int", "f": "int"}
        ns.update(b="x", c=field(default_factory=tuple), d=field(default=3, repr=False, compare=False),
                  e=field(default_factory=lambda: [7], init=False, compare=False), f=field(default=5, init=False))
        if docstring:
            ns["__doc__"] = "A record."
        if post_init:
            def __post_init__(self):
                object.__setattr__(self, "g", self.a * 2) if not options.get("slots") else None
            ns["__post_init__"] = __post_init__
        ns["__module__"] = "_record_twins"

    cls = types.new_class(name, (), {}, body)
    cls.__qualname__ = name
    cls = decorator(**options)(cls)
    setattr(sys.modules["_record_twins"], name, cls)
    return cls


@pytest.fixture
def twins():
    _module()

    def make(options, **kw):
        return (_declare(record, "R", options, **kw), _declare(dataclasses.dataclass, "D", options, **kw))
    yield make
    sys.modules.pop("_record_twins", None)


def _same_repr(r, d):
    return repr(r).replace("R(", "D(", 1) == repr(d)


@pytest.mark.parametrize("options", OPTIONS, ids=lambda o: ",".join(o) or "plain")
def test_record_matches_dataclass(twins, options):
    R, D = twins(options, post_init=True)
    assert str(inspect.signature(R)) == str(inspect.signature(D))
    assert R.__match_args__ == D.__match_args__
    assert [f.name for f in dataclasses.fields(R)] == [f.name for f in dataclasses.fields(D)]
    for flag in ("init", "repr", "eq", "frozen"):
        assert getattr(R.__dataclass_params__, flag) == getattr(D.__dataclass_params__, flag), flag
    assert dataclasses.is_dataclass(R)

    for args, kwargs in [((1,), {}), ((1, "y"), {"c": (2,)}), ((), {"a": 4, "d": 9})]:
        r, d = R(*args, **kwargs), D(*args, **kwargs)
        assert _same_repr(r, d) if options.get("repr", True) else "object at" in repr(r)
        assert dataclasses.asdict(r) == dataclasses.asdict(d)
        assert (r.e, r.f) == (d.e, d.f) == ([7], 5)
        assert r.e is not R(*args, **kwargs).e  # a factory per instance
        if not options.get("slots"):
            assert r.g == d.g == 2 * r.a  # __post_init__ ran
        same = R(*args, **{**kwargs, "d": 100})  # d is compare=False
        if options.get("eq", True):
            assert (r == same) and not (r != same) and r != R(99)
            assert (r == d) is False  # another class: NotImplemented both ways, then identity
        else:
            assert r != same and r == r
        if options.get("eq", True) and not options.get("frozen"):
            assert R.__hash__ is None and D.__hash__ is None
        elif options.get("eq", True):
            assert hash(r) == hash(d) == hash(same)
        else:
            assert hash(r) == object.__hash__(r)
        if options.get("frozen"):
            for obj in (r, d):
                with pytest.raises(FrozenInstanceError, match="cannot assign to field 'a'"):
                    obj.a = 2
                with pytest.raises(FrozenInstanceError, match="cannot delete field 'b'"):
                    del obj.b
                # (the standard library's frozen+slots __setattr__ raises TypeError here: Python 3.11's bug)
                with pytest.raises(AttributeError if obj is r else (AttributeError, TypeError)):
                    obj.new_attribute = 1
        else:
            r.a = 5
            assert r.a == 5
        assert dataclasses.replace(r, b="z").b == "z" and dataclasses.replace(r, b="z").a == r.a
        assert pickle.loads(pickle.dumps(r)) == r or not options.get("eq", True)
        assert dataclasses.asdict(copy.deepcopy(r)) == dataclasses.asdict(r)


@pytest.mark.parametrize("call", [lambda C: C(), lambda C: C(1, "x", [], 3, 4), lambda C: C(1, z=2),
                                  lambda C: C(1, a=2), lambda C: C(1, e=2)])
def test_wrong_arguments_raise_type_error_like_dataclass(twins, call):
    R, D = twins({})
    with pytest.raises(TypeError):
        call(D)
    with pytest.raises(TypeError, match="R()"):
        call(R)


def test_class_docstring_and_explicit_methods_are_as_dataclass_makes_them(twins):
    R, D = twins({"frozen": True}, docstring=False)
    assert R.__doc__.replace("R(", "D(", 1) == D.__doc__

    for deco in (record, dataclasses.dataclass):
        @deco(frozen=True)
        class Explicit:
            a: int

            def __hash__(self):
                return 42

            def __repr__(self):
                return "mine"

        assert hash(Explicit(1)) == 42 and repr(Explicit(1)) == "mine" and Explicit(1) == Explicit(1)

        @deco
        class OwnEq:
            a: int

            def __eq__(self, other):
                return True

        assert OwnEq(1) == 5 and OwnEq.__hash__ is None


def test_recursive_repr_and_inheritance(twins):
    R, D = twins({})
    r, d = R(1, c=[]), D(1, c=[])
    r.c.append(r)
    d.c.append(d)
    assert _same_repr(r, d) and "..." in repr(r)

    @record(frozen=True)
    class Base:
        a: int

    @record(frozen=True)
    class Child(Base):
        b: int = 2

    assert Child(1) == Child(1, 2) and hash(Child(1)) == hash((1, 2)) and repr(Child(1)).endswith("Child(a=1, b=2)")
    with pytest.raises(FrozenInstanceError):
        Child(1).b = 3

    @dataclasses.dataclass(frozen=True)  # a user's frozen dataclass may extend a frozen record
    class UserChild(Base):
        c: int = 0

    assert UserChild(1).c == 0
    with pytest.raises(TypeError, match="non-frozen"):
        @record
        class Thawed(Base):
            b: int = 0
    with pytest.raises(TypeError, match="non-frozen"):
        @dataclasses.dataclass
        class Thawed2(Base):
            b: int = 0

    class Plain(Base):  # a plain subclass with its own __init__ shows its own signature
        def __init__(self, x, y):
            super().__init__(x + y)

    assert str(inspect.signature(Plain)) == "(x, y)" and Plain(1, 2).a == 3


@pytest.mark.parametrize("slots", [False, True])
def test_a_field_outside_init_without_default_stays_unset(slots):
    for deco in (record, dataclasses.dataclass):
        @deco(slots=slots)
        class Later:
            a: int
            b: int = field(init=False)
            c: int = field(default=4, init=False)

        obj = Later(1)
        assert obj.a == 1 and obj.c == 4 and not hasattr(obj, "b")
        obj.b = 2
        assert obj.b == 2 and str(inspect.signature(Later)).startswith("(a: int)")


@pytest.mark.parametrize("options", [{"order": True}, {"unsafe_hash": True}, {"kw_only": True}, {"spam": 1}])
def test_unsupported_options_are_refused(options):
    with pytest.raises(TypeError, match="@record does not support"):
        record(**options)


def test_lagrange_declares_its_records_with_record():
    """The architecture rule that keeps a warm re-run's imports free of compiled dataclass methods."""
    root = pathlib.Path(__file__).resolve().parents[1] / "lagrange"
    found = [f"{p.relative_to(root)}:{i}" for p in root.rglob("*.py") if p.name != "records.py"
             for i, line in enumerate(p.read_text().splitlines(), 1)
             if re.match(r"\s*@(dataclasses\.)?dataclass\b", line)]
    assert not found, found
