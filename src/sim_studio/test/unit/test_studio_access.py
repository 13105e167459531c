"""access.py: who may use the studio and which files it serves."""
import os

from sim_studio import access


def test_loopback_needs_no_token_and_other_hosts_get_a_random_one():
    assert access.choose_token("127.0.0.1") == ""
    assert access.choose_token("localhost") == ""
    assert access.choose_token("::1") == ""
    first, second = access.choose_token("0.0.0.0"), access.choose_token("0.0.0.0")
    assert len(first) >= 24 and first != second  # random each time, hard to guess
    assert access.choose_token("0.0.0.0", "mine") == "mine"


def test_the_printed_url_carries_the_token():
    assert access.page_url("127.0.0.1", 8080, "") == "http://127.0.0.1:8080/"
    assert access.page_url("0.0.0.0", 9000, "abc") == "http://127.0.0.1:9000/?token=abc"


def test_a_token_is_needed_only_when_one_is_set():
    assert access.token_accepted("", None, None)
    assert access.token_accepted("abc", None, "abc", None)
    assert not access.token_accepted("abc", None, None, None)
    assert not access.token_accepted("abc", "abd", "", None)


def test_files_outside_the_root_are_not_served(tmp_path):
    (tmp_path / "www").mkdir()
    (tmp_path / "www" / "index.html").write_text("page")
    (tmp_path / "secret").write_text("no")
    root = str(tmp_path / "www")
    assert access.file_under(root, "index.html") == os.path.join(root, "index.html")
    for bad in ("../secret", "/../secret", "a/../../secret", "..\\secret", "index.html\0", "", "."):
        assert access.file_under(root, bad) is None, bad
    assert access.file_under(root, "/index.html") == os.path.join(root, "index.html")  # a leading / is the root
