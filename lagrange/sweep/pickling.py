"""Pickling a sweep task once for all its runs (its own module: :mod:`lagrange.sweep.task` and
:mod:`lagrange.sweep.identity` both need it, and neither may import the other's users back)."""

from __future__ import annotations

import pickle

from ..errors import SweepError

__all__ = ["dumps_task"]


def dumps_task(task) -> bytes:
    """Pickle a task once for all runs (cloudpickle when installed: lambdas and notebook functions travel
    too). Raises SweepError saying what to change when it cannot be pickled."""
    try:
        import cloudpickle

        return cloudpickle.dumps(task)
    except ImportError:
        pass
    except Exception as exc:  # noqa: BLE001 - cloudpickle raises many types; report one clear error
        raise SweepError(f"the sweep task cannot be sent to worker processes: {type(exc).__name__}: {exc}. "
                         "Run it in this process with workers=0") from None
    try:
        return pickle.dumps(task)
    except Exception as exc:  # noqa: BLE001
        raise SweepError(f"the sweep task cannot be pickled for worker processes ({type(exc).__name__}: {exc}): "
                         "summary, setup and event functions must be module-level functions (or install "
                         "cloudpickle), or run in this process with workers=0") from None
