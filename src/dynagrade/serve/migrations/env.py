"""Alembic environment: migrations run on the connection :func:`dynagrade.serve.db.migrate`
passes in (the server runs ``upgrade head`` on start; no alembic.ini is needed)."""

from alembic import context

from dynagrade.serve.db import metadata

connection = context.config.attributes["connection"]
context.configure(connection=connection, target_metadata=metadata)
context.run_migrations()
