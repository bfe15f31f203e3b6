"""Rendering: terminal tables, sheets, answer keys and reports."""
