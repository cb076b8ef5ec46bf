"""Lark grammars of the EdingCNC dialect (package data)."""
