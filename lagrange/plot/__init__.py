"""Plots of trajectories (the only package that imports matplotlib)."""

from .animate import InlineAnimation, animate, animation_html, scene_points
from .trajectory import plot_trajectory
from .workprecision import plot_work_precision

__all__ = ["plot_trajectory", "animate", "animation_html", "scene_points", "plot_work_precision",
           "InlineAnimation"]
