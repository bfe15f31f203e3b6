"""The exercise bank shipped with dynagrade (installed as ``dynagrade.bank``).

Each file below a chapter folder defines one ``EXERCISE``; see docs/authoring.md.
"""
