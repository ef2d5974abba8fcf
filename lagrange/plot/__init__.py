"""Plots of trajectories (the only package that imports matplotlib)."""

from .trajectory import plot_trajectory

__all__ = ["plot_trajectory"]
