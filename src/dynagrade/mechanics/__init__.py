"""The mechanics core: one module per topic of the course, SI units throughout.

Each function returns one physical quantity and cites the relation of the
lecture notes it implements. Nothing here imports from the rest of dynagrade.
"""
