"""What the staff do on the server: exceptions to the policy per student, the start of a
timed exam, points by hand, regrades (with the verdicts they replaced), and named,
revocable staff links.

Revision ID: 0004
Revises: 0003
"""

import sqlalchemy as sa
from alembic import op

revision = "0004"
down_revision = "0003"
branch_labels = None
depends_on = None


def upgrade() -> None:
    with op.batch_alter_table("tokens") as tokens:
        tokens.add_column(sa.Column("label", sa.String(200), nullable=True))
        tokens.add_column(sa.Column("revoked_at", sa.DateTime(timezone=True), nullable=True))
    op.create_table(
        "allowances",
        sa.Column("exam_id", sa.String(200), primary_key=True),
        sa.Column("student_id", sa.String(200), primary_key=True),
        sa.Column("opens", sa.DateTime(timezone=True), nullable=True),
        sa.Column("closes", sa.DateTime(timezone=True), nullable=True),
        sa.Column("extra_minutes", sa.Integer, nullable=False, server_default="0"),
        sa.Column("extra_attempts", sa.Text, nullable=False, server_default="{}"),
        sa.Column("updated_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("updated_by", sa.String(200), nullable=False),
    )
    op.create_table(
        "starts",
        sa.Column("exam_id", sa.String(200), primary_key=True),
        sa.Column("student_id", sa.String(200), primary_key=True),
        sa.Column("started_at", sa.DateTime(timezone=True), nullable=False),
    )
    op.create_table(
        "overrides",
        sa.Column("exam_id", sa.String(200), primary_key=True),
        sa.Column("student_id", sa.String(200), primary_key=True),
        sa.Column("exercise_id", sa.String(200), primary_key=True),
        sa.Column("part", sa.String(200), primary_key=True),
        sa.Column("points", sa.Float, nullable=False),
        sa.Column("comment", sa.Text, nullable=False, server_default=""),
        sa.Column("author", sa.String(200), nullable=False),
        sa.Column("at", sa.DateTime(timezone=True), nullable=False),
    )
    op.create_table(
        "regrades",
        sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
        sa.Column("exam_id", sa.String(200), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("actor", sa.String(200), nullable=False),
        sa.Column("state", sa.String(16), nullable=False),
        sa.Column("source", sa.Text, nullable=False),
        sa.Column("plan", sa.Text, nullable=False),
        sa.Column("applied_at", sa.DateTime(timezone=True), nullable=True),
    )
    op.create_index("ix_regrades_exam_id", "regrades", ["exam_id"])
    op.create_table(
        "verdict_history",
        sa.Column("id", sa.Integer, primary_key=True, autoincrement=True),
        sa.Column("answer_id", sa.Integer, sa.ForeignKey("answers.id"), nullable=False),
        sa.Column("regrade_id", sa.Integer, sa.ForeignKey("regrades.id"), nullable=False),
        sa.Column("status", sa.String(32), nullable=False),
        sa.Column("correct", sa.Boolean, nullable=False),
        sa.Column("score", sa.Float, nullable=False),
        sa.Column("feedback", sa.Text, nullable=False),
        sa.Column("misconception", sa.Text, nullable=True),
    )
    op.create_index("ix_verdict_history_answer_id", "verdict_history", ["answer_id"])


def downgrade() -> None:
    op.drop_table("verdict_history")
    op.drop_table("regrades")
    op.drop_table("overrides")
    op.drop_table("starts")
    op.drop_table("allowances")
    with op.batch_alter_table("tokens") as tokens:
        tokens.drop_column("revoked_at")
        tokens.drop_column("label")
