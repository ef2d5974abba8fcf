"""Integration of numeric models: scipy's methods, switching (friction), the simulate driver."""
