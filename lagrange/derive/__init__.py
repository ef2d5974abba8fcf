"""Pure functions from a System to its equations."""
