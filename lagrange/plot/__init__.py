"""Plots of trajectories (the only package that imports matplotlib)."""

from .animate import animate, animation_html, scene_points
from .trajectory import plot_trajectory

__all__ = ["plot_trajectory", "animate", "animation_html", "scene_points"]
