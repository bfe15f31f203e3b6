"""LTI Assignment and Grade Services: the launched students and their platform's
endpoints, the exam's line item on each platform, and the scores queued, sent and
answered (:mod:`dynagrade.serve.lti.grades_store`).

Revision ID: 0006
Revises: 0005
"""

import sqlalchemy as sa
from alembic import op

revision = "0006"
down_revision = "0005"
branch_labels = None
depends_on = None


def upgrade() -> None:
    op.create_table(
        "lti_members",
        sa.Column("exam_id", sa.String(200), primary_key=True),
        sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"),
                  primary_key=True),
        sa.Column("student_id", sa.String(200), primary_key=True),
        sa.Column("sub", sa.String(400), nullable=False),
        sa.Column("resource_link_id", sa.String(400), nullable=True),
        sa.Column("lineitems_url", sa.Text, nullable=True),
        sa.Column("lineitem_url", sa.Text, nullable=True),
        sa.Column("scopes", sa.Text, nullable=False, server_default="[]"),
        sa.Column("launched_at", sa.DateTime(timezone=True), nullable=False),
    )
    op.create_table(
        "lti_line_items",
        sa.Column("exam_id", sa.String(200), primary_key=True),
        sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"),
                  primary_key=True),
        sa.Column("lineitem_url", sa.Text, nullable=False),
    )
    op.create_table(
        "lti_scores",
        sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
        sa.Column("exam_id", sa.String(200), nullable=False),
        sa.Column("platform_id", sa.Integer, sa.ForeignKey("lti_platforms.id"),
                  nullable=False),
        sa.Column("student_id", sa.String(200), nullable=False),
        sa.Column("body", sa.Text, nullable=False),
        sa.Column("state", sa.String(16), nullable=False),
        sa.Column("attempts", sa.Integer, nullable=False, server_default="0"),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("next_try_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("sent_at", sa.DateTime(timezone=True), nullable=True),
        sa.Column("answer_status", sa.Integer, nullable=True),
        sa.Column("answer_text", sa.Text, nullable=True),
        sa.Index("ix_lti_scores_exam_student", "exam_id", "student_id"),
    )


def downgrade() -> None:
    op.drop_table("lti_scores")
    op.drop_table("lti_line_items")
    op.drop_table("lti_members")
