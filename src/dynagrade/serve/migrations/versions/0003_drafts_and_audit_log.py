"""Drafts (what a student typed and has not submitted) and the audit log of the staff's
changes (a policy changed without regenerating the exam, ...).

Revision ID: 0003
Revises: 0002
"""

import sqlalchemy as sa
from alembic import op

revision = "0003"
down_revision = "0002"
branch_labels = None
depends_on = None


def upgrade() -> None:
    op.create_table(
        "drafts",
        sa.Column("exam_id", sa.String(200), primary_key=True),
        sa.Column("student_id", sa.String(200), primary_key=True),
        sa.Column("exercise_id", sa.String(200), primary_key=True),
        sa.Column("part", sa.String(200), primary_key=True),
        sa.Column("text", sa.Text, nullable=False),
        sa.Column("saved_at", sa.DateTime(timezone=True), nullable=False),
    )
    op.create_table(
        "audit_log",
        sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
        sa.Column("exam_id", sa.String(200), nullable=False),
        sa.Column("at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("actor", sa.String(200), nullable=False),
        sa.Column("action", sa.String(64), nullable=False),
        sa.Column("subject", sa.String(200), nullable=False),
        sa.Column("before", sa.Text, nullable=True),
        sa.Column("after", sa.Text, nullable=True),
    )
    op.create_index("ix_audit_log_exam_action", "audit_log", ["exam_id", "action"])


def downgrade() -> None:
    op.drop_table("audit_log")
    op.drop_table("drafts")
