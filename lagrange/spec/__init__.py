"""Loading systems from specs: problem ids, Python files and safe TOML files."""
