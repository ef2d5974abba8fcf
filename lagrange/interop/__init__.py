"""Interop with other libraries' models (one module per library)."""
