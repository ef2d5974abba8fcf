"""Plots of trajectories (the only package that imports matplotlib).

No function here calls ``matplotlib.use``: figures written to files are drawn on their own Agg canvas outside
pyplot, figures returned for display come from pyplot and show the way the user's backend shows them.
"""

from .animate import InlineAnimation, animate, animation_html, scene_points
from .trajectory import PlotError, plot_trajectory
from .workprecision import plot_work_precision

__all__ = ["plot_trajectory", "animate", "animation_html", "scene_points", "plot_work_precision",
           "InlineAnimation", "PlotError"]
