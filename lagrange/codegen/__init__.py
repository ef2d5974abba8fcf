"""Code generation: Equations -> NumericModel (python, numba, reference backends)."""
