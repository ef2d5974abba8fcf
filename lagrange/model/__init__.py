"""What users declare: coordinates, parameters, bodies, forces and the System."""
