"""LTI Deep Linking: a platform's request to place content, waiting for the staff's
choice (:mod:`dynagrade.serve.lti.deep_linking`).

Revision ID: 0008
Revises: 0007
"""

import sqlalchemy as sa
from alembic import op

revision = "0008"
down_revision = "0007"
branch_labels = None
depends_on = None


def upgrade() -> None:
    op.create_table(
        "lti_deep_links",
        sa.Column("session_hash", sa.String(64), primary_key=True),
        sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"),
                  nullable=False),
        sa.Column("deployment_id", sa.String(400), nullable=False),
        sa.Column("return_url", sa.Text, nullable=False),
        sa.Column("data", sa.Text, nullable=True),
        sa.Column("accept_multiple", sa.Boolean, nullable=False),
    )


def downgrade() -> None:
    op.drop_table("lti_deep_links")
