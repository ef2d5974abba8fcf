"""A numba compiler pipeline that marks every array argument ``noalias`` (C's ``restrict``).

numba cannot tell that the arrays a kernel reads and the arrays it writes are different memory, so LLVM's
loop vectorizer must test at run time whether they overlap; past a handful of arrays (the rows of a 10-link
pendulum's state) it gives up and the loop stays scalar. The batched right-hand side
(:mod:`lagrange.codegen.batch_source`) never receives overlapping arrays (its caller allocates ``out`` and
the scratch rows), so it is compiled with ``pipeline_class=NoAliasCompiler``: the same IEEE arithmetic,
vectorized across members. Never use it for a function whose array arguments may overlap.
"""

from __future__ import annotations

from numba.core.compiler import Compiler

__all__ = ["NoAliasCompiler"]


class NoAliasCompiler(Compiler):
    """numba's default pipeline with ``flags.noalias = True`` (array arguments never overlap)."""

    def __init__(self, typingctx, targetctx, library, args, return_type, flags, locals):
        flags.noalias = True
        super().__init__(typingctx, targetctx, library, args, return_type, flags, locals)
