"""Worked examples and problems of D. A. Wells, *Lagrangian Dynamics* (Schaum), with the book's answers.

Installed as the package ``lagrange_problems``; one module per book problem (see
``lagrange.corpus.Problem``). Module names: ``chNN_<id>.py``.
"""
