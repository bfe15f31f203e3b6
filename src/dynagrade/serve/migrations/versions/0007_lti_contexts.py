"""LTI Names and Role Provisioning Services: where each platform lists the course's
members (:mod:`dynagrade.serve.lti.grades_store`).

Revision ID: 0007
Revises: 0006
"""

import sqlalchemy as sa
from alembic import op

revision = "0007"
down_revision = "0006"
branch_labels = None
depends_on = None


def upgrade() -> None:
    op.create_table(
        "lti_contexts",
        sa.Column("exam_id", sa.String(200), primary_key=True),
        sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"),
                  primary_key=True),
        sa.Column("memberships_url", sa.Text, nullable=False),
    )


def downgrade() -> None:
    op.drop_table("lti_contexts")
