"""`dynagrade lti`: a platform registered (again: replaced), the values Moodle's and
Canvas's forms ask for printed from the base URL, the tool's key rotated with the old
key published until it is retired."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from serve_support import exam_copy, exam_dir  # noqa: F401

BASE = "https://exam.example.org/dyn"


@pytest.fixture
def manifest(exam_dir, tmp_path):
    return exam_copy(exam_dir, tmp_path / "exam")


def run(*args: str) -> str:
    from dynagrade.cli import main

    result = CliRunner().invoke(main, ["lti", *args])
    assert result.exit_code == 0, result.output
    return result.output


def _engine(manifest):
    from dynagrade.serve import db

    return db.connect(db.sqlite_url_beside(manifest))


def test_register_stores_the_platform_and_registering_again_replaces_it(manifest):
    from dynagrade.serve.lti import store

    moodle = "https://moodle.example.org"
    common = ["--issuer", moodle, "--client-id", "abc123", "--auth-url",
              f"{moodle}/mod/lti/auth.php", "--token-url", f"{moodle}/mod/lti/token.php",
              "--jwks-url", f"{moodle}/mod/lti/certs.php"]
    run("register", str(manifest), *common, "--deployment-id", "1")
    out = run("register", str(manifest), *common, "--deployment-id", "1",
              "--deployment-id", "7", "--user-claim", "sourcedid")
    assert "students found by sourcedid" in out
    (platform,) = store.all_platforms(_engine(manifest))
    assert platform.deployment_ids == ("1", "7") and platform.user_claim == "sourcedid"
    assert platform.jwks_url == "https://moodle.example.org/mod/lti/certs.php"


def test_show_prints_the_values_the_registration_forms_ask_for(manifest):
    out = run("show", str(manifest), "--base-url", BASE + "/")
    lines = out.splitlines()
    assert f"  Tool URL: {BASE}/lti/launch" in lines
    assert f"  Public keyset URL: {BASE}/lti/jwks" in lines
    assert f"  Initiate login URL: {BASE}/lti/login" in lines
    assert f"  Redirection URI(s): {BASE}/lti/launch" in lines
    assert f"  Content Selection URL (deep linking): {BASE}/lti/launch" in lines
    canvas = json.loads(out[out.index("{"):out.rindex("}") + 1])
    assert canvas["oidc_initiation_url"] == f"{BASE}/lti/login"
    assert canvas["target_link_uri"] == f"{BASE}/lti/launch"
    assert canvas["public_jwk_url"] == f"{BASE}/lti/jwks"
    assert canvas["extensions"][0]["platform"] == "canvas.instructure.com"
    placements = canvas["extensions"][0]["settings"]["placements"]
    assert {p["placement"] for p in placements} == {"link_selection", "assignment_selection"}
    assert {p["message_type"] for p in placements} == {"LtiDeepLinkingRequest"}
    ags = "https://purl.imsglobal.org/spec/lti-ags/scope/"
    nrps = "https://purl.imsglobal.org/spec/lti-nrps/scope/contextmembership.readonly"
    assert set(canvas["scopes"]) == {ags + "lineitem", ags + "score", nrps}


def test_rotate_key_keeps_the_old_key_published_until_retire_old(manifest):
    from dynagrade.serve.lti import keys

    engine = _engine(manifest)
    first = keys.signing_key(engine).kid
    out = run("rotate-key", str(manifest))
    second = keys.signing_key(engine).kid
    assert second != first and f"new key {second}" in out
    assert {k["kid"] for k in keys.jwks(engine)["keys"]} == {first, second}
    out = run("rotate-key", str(manifest), "--retire-old")
    assert f"retired {first}" in out
    assert [k["kid"] for k in keys.jwks(engine)["keys"]] == [second]
