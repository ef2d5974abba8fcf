"""Records: dataclasses whose methods are not compiled when their module is imported.

Python 3.11's ``@dataclass`` writes a class's ``__init__``, ``__repr__``, ``__eq__``, ``__hash__``,
``__setattr__`` and ``__delattr__`` as source text and compiles each with ``exec``: 1–5 ms per class. About
twenty of lagrange's record classes lie on the path of a warm re-run (model, equations, run request, method
registry, trajectory, tape), and their compilation was about 38 ms — a quarter of lagrange's own work in the
warm re-run of a small model (``benchmarks/rerun.py``, issue #23 item 4). ``@record`` makes the same class with
the same behaviour from generic methods that read the class's fields when they run: nothing is compiled, and
the class is still a dataclass for :func:`dataclasses.fields`, :func:`~dataclasses.replace`,
:func:`~dataclasses.asdict` and :func:`~dataclasses.is_dataclass`.

Behaviour, as ``@dataclass`` with the same options (``tests/test_records.py`` compares the two, option by
option, on the same classes):

* ``init``: ``__init__(self, <fields with init=True, in field order>)`` with the fields' defaults; a
  ``default_factory`` is called per instance (also for fields with ``init=False``); ``__post_init__`` is called
  last. Wrong arguments raise :class:`TypeError` naming the class and the argument.
  :func:`inspect.signature` of the class shows the same parameters, defaults (``<factory>``) and annotations.
* ``repr``: ``ClassName(a=..., b=...)`` over the fields with ``repr=True`` (``...`` for a recursive reference).
* ``eq``: equal when of the same class and the tuples of the fields with ``compare=True`` are equal; else
  ``NotImplemented``.
* ``frozen``: assigning or deleting an attribute raises :class:`dataclasses.FrozenInstanceError`; with ``eq``,
  ``__hash__`` is the hash of the tuple of the fields with ``hash=True`` (``hash=None``: ``compare``); a
  mutable class with ``eq`` is unhashable. An explicit ``__hash__`` (or ``__init__``, ``__repr__``,
  ``__eq__``) in the class body is kept, as ``@dataclass`` keeps it.
* ``slots``: the class is rebuilt with ``__slots__`` by :func:`dataclasses.dataclass` itself (no code is
  generated for that); frozen slotted instances pickle.
* ``__match_args__``, the class docstring when there is none, and the frozen/non-frozen inheritance checks are
  the standard library's; ``__dataclass_params__`` reports the options given.

A class that inherits fields from another dataclass gets its frozen ``__setattr__``/``__delattr__`` compiled by
the standard library (its inheritance check needs the flag); the rest stays generic. Not supported (a
:class:`TypeError` at decoration): ``order``, ``unsafe_hash``, ``kw_only``, ``match_args=False``,
``weakref_slot`` and ``InitVar`` or keyword-only fields — lagrange uses none of them. Building an instance costs
a few microseconds more than the compiled ``__init__``; no record is built per integration step.
"""

from __future__ import annotations

import dataclasses
from _thread import get_ident
from dataclasses import MISSING, FrozenInstanceError

__all__ = ["record"]


class _Factory:
    """The default shown in a signature for a field with a ``default_factory`` (as ``@dataclass`` shows it)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "<factory>"


_FACTORY = _Factory()


class _Signature:
    """``inspect.signature(cls)`` of a record: its generated ``__init__``'s parameters, built on first use.

    ``None`` (inspect then looks further) for a subclass whose ``__init__`` is not the record's."""

    def __get__(self, instance, owner):
        init = next((k.__dict__["__init__"] for k in owner.__mro__ if "__init__" in k.__dict__), None)
        defining = getattr(init, "__record_class__", None)
        if defining is None:
            return None
        cached = defining.__dict__.get("__record_signature__")
        if cached is None:
            cached = _signature(defining)
            type.__setattr__(defining, "__record_signature__", cached)
        return cached


def _signature(cls):
    import inspect

    params = [inspect.Parameter("self", inspect.Parameter.POSITIONAL_OR_KEYWORD)]
    for f in dataclasses.fields(cls):
        if not f.init:
            continue
        default = (_FACTORY if f.default_factory is not MISSING
                   else f.default if f.default is not MISSING else inspect.Parameter.empty)
        params.append(inspect.Parameter(f.name, inspect.Parameter.POSITIONAL_OR_KEYWORD, default=default,
                                        annotation=f.type))
    return inspect.Signature(params[1:], return_annotation=None)


def _plan(cls) -> tuple:
    """``(parameter names, {name: index}, per field (name, init, default, factory))`` of ``cls``'s ``__init__``."""
    fields = dataclasses.fields(cls)
    names = tuple(f.name for f in fields if f.init)
    return names, {n: i for i, n in enumerate(names)}, tuple((f.name, f.init, f.default, f.default_factory)
                                                            for f in fields)


def _make_init(cls, frozen: bool, slots: bool):
    plan = None
    setter = object.__setattr__ if frozen else setattr

    def __init__(self, *args, **kwargs):
        nonlocal plan
        if plan is None:
            plan = _plan(cls)
        names, index, fields = plan
        if len(args) > len(names):
            raise TypeError(f"{cls.__qualname__}() takes {len(names)} positional argument(s) but {len(args)} "
                            "were given")
        values = dict(zip(names, args))
        for key, value in kwargs.items():
            if key not in index:
                raise TypeError(f"{cls.__qualname__}() got an unexpected keyword argument {key!r}")
            if key in values:
                raise TypeError(f"{cls.__qualname__}() got multiple values for argument {key!r}")
            values[key] = value
        for name, init, default, factory in fields:
            if init and name in values:
                value = values[name]
            elif factory is not MISSING:
                value = factory()
            elif not init:
                if not slots or default is MISSING:
                    continue  # (a plain default outside __init__: the class attribute holds it, unless slotted)
                value = default
            elif default is not MISSING:
                value = default
            else:
                raise TypeError(f"{cls.__qualname__}() missing required argument {name!r}")
            setter(self, name, value)
        post = getattr(self, "__post_init__", None)
        if post is not None:
            post()

    __init__.__record_class__ = cls
    return __init__


def _make_repr(cls):
    names = tuple(f.name for f in dataclasses.fields(cls) if f.repr)
    running = set()

    def __repr__(self):
        key = (id(self), get_ident())
        if key in running:
            return "..."
        running.add(key)
        try:
            return (f"{self.__class__.__qualname__}("
                    + ", ".join(f"{name}={getattr(self, name)!r}" for name in names) + ")")
        finally:
            running.discard(key)

    return __repr__


def _make_eq(cls):
    names = tuple(f.name for f in dataclasses.fields(cls) if f.compare)

    def __eq__(self, other):
        if other.__class__ is self.__class__:
            return tuple(getattr(self, n) for n in names) == tuple(getattr(other, n) for n in names)
        return NotImplemented

    return __eq__


def _make_hash(cls):
    names = tuple(f.name for f in dataclasses.fields(cls) if (f.compare if f.hash is None else f.hash))

    def __hash__(self):
        return hash(tuple(getattr(self, n) for n in names))

    return __hash__


def _make_frozen(cls):
    names = frozenset(f.name for f in dataclasses.fields(cls))

    def __setattr__(self, name, value):
        if type(self) is cls or name in names:
            raise FrozenInstanceError(f"cannot assign to field {name!r}")
        super(cls, self).__setattr__(name, value)

    def __delattr__(self, name):
        if type(self) is cls or name in names:
            raise FrozenInstanceError(f"cannot delete field {name!r}")
        super(cls, self).__delattr__(name)

    return __setattr__, __delattr__


def _getstate(self):
    return [getattr(self, f.name) for f in dataclasses.fields(self)]


def _setstate(self, state):
    for f, value in zip(dataclasses.fields(self), state):
        object.__setattr__(self, f.name, value)


#: ``@dataclass`` options ``@record`` accepts only at their defaults
_FIXED = {"order": False, "unsafe_hash": False, "kw_only": False, "weakref_slot": False, "match_args": True}


def record(cls=None, /, *, init: bool = True, repr: bool = True, eq: bool = True, frozen: bool = False,
           slots: bool = False, **unsupported):
    """``@record``, ``@record(frozen=True, ...)``: a dataclass with generic (not compiled) methods; see the
    module docstring for the contract."""
    refused = sorted(k for k, v in unsupported.items() if k not in _FIXED or v != _FIXED[k])
    if refused:
        raise TypeError(f"@record does not support {', '.join(refused)} (use @dataclasses.dataclass)")

    def wrap(klass):
        own = dict(klass.__dict__)
        class_hash = own.get("__hash__", MISSING)
        explicit_hash = not (class_hash is MISSING or (class_hash is None and "__eq__" in own))
        inherits = any(hasattr(b, "__dataclass_fields__") for b in klass.__mro__[1:])
        if "__signature__" not in own:
            klass.__signature__ = _Signature()
        if not own.get("__doc__"):  # (written below from the record's signature: the standard library would
            klass.__doc__ = "-"    # ask inspect for object's, which parses it from text: 6 ms a class)
        klass = dataclasses.dataclass(klass, init=False, repr=False, eq=False, frozen=frozen and inherits,
                                      slots=slots)
        for f in dataclasses.fields(klass):
            if f.kw_only:
                raise TypeError(f"@record: keyword-only field {f.name!r} of {klass.__qualname__} is not supported")
        if any(f._field_type is dataclasses._FIELD_INITVAR for f in klass.__dataclass_fields__.values()):
            raise TypeError(f"@record: InitVar fields of {klass.__qualname__} are not supported")
        methods = {}
        if init and "__init__" not in own:
            methods["__init__"] = _make_init(klass, frozen, slots)
        if repr and "__repr__" not in own:
            methods["__repr__"] = _make_repr(klass)
        if eq and "__eq__" not in own:
            methods["__eq__"] = _make_eq(klass)
        if eq and not explicit_hash:
            methods["__hash__"] = _make_hash(klass) if frozen else None
        if frozen and not inherits:
            if "__setattr__" in own or "__delattr__" in own:
                raise TypeError(f"Cannot overwrite attribute __setattr__ in class {klass.__name__}")
            methods["__setattr__"], methods["__delattr__"] = _make_frozen(klass)
        if frozen and slots:  # (pickling: the frozen __setattr__ would refuse the default slot restore)
            for name, method in (("__getstate__", _getstate), ("__setstate__", _setstate)):
                if name not in own:
                    methods[name] = method
        for name, method in methods.items():
            if method is not None and method not in (_getstate, _setstate):
                method.__qualname__ = f"{klass.__qualname__}.{name}"
                method.__module__ = klass.__module__
            type.__setattr__(klass, name, method)
        params = klass.__dataclass_params__
        params.init, params.repr, params.eq, params.frozen = init, repr, eq, frozen
        if not own.get("__doc__"):  # as @dataclass writes it, from the record's own signature
            import inspect

            klass.__doc__ = klass.__name__ + str(inspect.signature(klass)).replace(" -> None", "")
        return klass

    return wrap if cls is None else wrap(cls)
