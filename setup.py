"""Build hook: the C Taylor interpreter as an optional extension module (the metadata is in pyproject.toml).

``optional=True``: without a C compiler (or when the build fails) the install still succeeds, and
lagrange builds the interpreter at run time instead (lagrange.codegen.c_interpreter).
"""

import sys

from setuptools import Extension, setup


def extensions() -> list:
    """``lagrange.integrate._ctaylor``: the tape interpreter with an empty module init (called via ctypes)."""
    flags = [] if sys.platform == "win32" else ["-std=c99", "-ffp-contract=off"]
    return [Extension("lagrange.integrate._ctaylor", sources=["lagrange/integrate/_taylor_interp.c"],
                      define_macros=[("LAGRANGE_PY_EXTENSION", "1")], extra_compile_args=flags, optional=True)]


if __name__ == "__main__":  # setuptools' build backend runs this file as __main__
    setup(ext_modules=extensions())
