"""Results of integration: the Trajectory and its diagnostics."""
