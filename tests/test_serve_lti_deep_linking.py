"""Deep Linking against the test platform: a teacher's LtiDeepLinkingRequest opens the
page of what to place; the answer is an LtiDeepLinkingResponse the tool signed (checked
here with the tool's published keys), carrying the platform's data and one resource
link: the exam with its points as a line item, or in practice mode one exercise, whose
launch opens the student's page at that exercise. A learner cannot place anything."""

from __future__ import annotations

import html
import re

import jwt

from dynagrade.serve import limits
from lti_platform import CLIENT_ID, DEPLOYMENT_ID
from lti_support import TOOL, begin, platform, post_launch, tool  # noqa: F401
from serve_support import exam_copy, exam_dir  # noqa: F401

DL = "https://purl.imsglobal.org/spec/lti-dl/claim/"
LTI = "https://purl.imsglobal.org/spec/lti/claim/"


def deep_launch(client, platform, user: str):
    state, nonce = begin(client, platform, user)
    token = platform.sign(platform.deep_linking_claims(platform.users[user], nonce))
    return post_launch(client, token, state)


def placed(client, platform, choice: str) -> dict:
    """A teacher's deep-linking launch and ``choice``: the answer's claims, verified
    with the key the tool publishes."""
    answer = deep_launch(client, platform, "u-prof")
    assert answer.status_code == 303, answer.text
    place = answer.headers["location"]
    assert re.fullmatch(r"/i/lti-[0-9a-f]{40}/lti/place", place)
    handle = place.split("/")[2]
    assert 'name="choice"' in client.get(place).text
    page = client.post(place, data={"choice": choice, "csrf": limits.csrf_field(
        client.app.state.server.secret, handle)})
    assert page.status_code == 200, page.text
    assert f'action="{platform.url}/deep-link-return"' in page.text
    assert f"form-action 'self' {platform.url}" in page.headers["content-security-policy"]
    signed = html.unescape(re.search(r'name="JWT" value="([^"]+)"', page.text).group(1))
    keys = client.get("/lti/jwks").json()["keys"]
    kid = jwt.get_unverified_header(signed)["kid"]
    key = jwt.PyJWK(next(k for k in keys if k["kid"] == kid)).key
    return jwt.decode(signed, key, algorithms=["RS256"], audience=platform.issuer)


def test_a_teacher_places_the_exam_with_its_points_as_a_line_item(exam_dir, tmp_path,
                                                                    platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, None, platform) as client:
        found = placed(client, platform, "exam")
        assert found["iss"] == CLIENT_ID
        assert found[LTI + "message_type"] == "LtiDeepLinkingResponse"
        assert found[LTI + "version"] == "1.3.0"
        assert found[LTI + "deployment_id"] == DEPLOYMENT_ID
        assert found[DL + "data"] == "platform-data-42"
        assert found["nonce"] and found["exp"] - found["iat"] == 300
        (item,) = found[DL + "content_items"]
        assert item == {"type": "ltiResourceLink", "title": "Serve test",
                        "url": f"{TOOL}/lti/launch",
                        "lineItem": {"scoreMaximum": 10.0, "label": "Serve test",
                                     "resourceId": client.app.state.server.data.exam_id}}


def test_in_practice_mode_one_exercise_is_placed_and_its_launch_opens_it(exam_dir, tmp_path,
                                                                         platform):
    manifest = exam_copy(exam_dir, tmp_path / "pr", mode="practice", feedback="immediate")
    with tool(manifest, None, platform) as client:
        found = placed(client, platform, "exercise:sliding-up-a-slope")
        (item,) = found[DL + "content_items"]
        assert item["custom"] == {"exercise": "sliding-up-a-slope"}
        assert "lineItem" not in item  # practice is not graded
        state, nonce = begin(client, platform, "u-ada")
        claims = {**platform.claims(platform.users["u-ada"], nonce),
                  LTI + "custom": item["custom"]}
        answer = post_launch(client, platform.sign(claims), state)
        assert answer.status_code == 303
        assert re.fullmatch(r"/s/lti-[0-9a-f]{40}#sliding-up-a-slope",
                            answer.headers["location"])


def test_an_exam_offers_no_single_exercise_to_place(exam_dir, tmp_path, platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, None, platform) as client:
        answer = deep_launch(client, platform, "u-prof")
        page = client.get(answer.headers["location"]).text
        assert page.count('name="choice"') == 1


def test_a_learner_cannot_place_content(exam_dir, tmp_path, platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, None, platform) as client:
        answer = deep_launch(client, platform, "u-ada")
        assert answer.status_code == 403 and "teachers place" in answer.text
        assert "dynagrade_lti=" not in answer.headers.get("set-cookie", "")
