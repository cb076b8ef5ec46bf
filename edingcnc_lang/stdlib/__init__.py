"""The packaged default macro file (package data)."""
