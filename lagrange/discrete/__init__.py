"""Discrete (molecular) models: the energy-conserving pair-potential integrator and Greenspan's top."""
