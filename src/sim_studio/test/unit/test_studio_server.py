"""server.py on a real socket, without ROS: files, the token, odd methods and bad websocket
messages. A test view stands in for the real ones."""
import asyncio
import json

import aiohttp
import pytest
import yarl

from sim_studio.server import MAX_MESSAGE_BYTES, Studio
from sim_studio.view import View


class Echo(View):
    name = "echo"

    async def handle(self, client, message):
        if message["type"] == "fail":
            raise RuntimeError("a bug")
        if message["type"] == "bad":
            raise ValueError("field x: expected a number")
        client.reply(message, text=message.get("text"))


def serve(tmp_path, token, check):
    www = tmp_path / "www"
    www.mkdir()
    (www / "index.html").write_text("<html>studio</html>")
    (tmp_path / "secret.txt").write_text("secret")

    async def run():
        studio = Studio("127.0.0.1", 0, token, {"": str(www)})
        studio.add_views([Echo(studio)])
        await studio.start()
        try:
            async with aiohttp.ClientSession(cookie_jar=aiohttp.CookieJar(unsafe=True)) as session:  # cookies for an IP
                await check(session, "http://127.0.0.1:%d" % studio.port)
        finally:
            await studio.stop()
    asyncio.run(run())


async def status(session, method, url):
    # encoded=True: the path goes out as written, ../ and all, as an attacker would send it
    async with session.request(method, yarl.URL(url, encoded=True)) as response:
        return response.status, await response.text()


def test_files_methods_and_traversal(tmp_path):
    async def check(session, base):
        assert await status(session, "GET", base + "/") == (200, "<html>studio</html>")
        code, text = await status(session, "POST", base + "/index.html")
        assert code == 405 and "POST is not allowed" in text
        assert (await status(session, "DELETE", base + "/"))[0] == 405
        for path in ("/../secret.txt", "/%2e%2e/secret.txt", "/views/echo/__init__.py", "/views/none/view.js"):
            code, text = await status(session, "GET", base + path)
            assert code == 404 and "secret" not in text.replace("/secret.txt", ""), path
        listed = json.loads((await status(session, "GET", base + "/views.json"))[1])
        assert listed == [{"name": "echo", "title": "echo", "slot": "tab", "order": 100}]
    serve(tmp_path, "", check)


def test_status_counts_the_pages_attached_and_forgets_a_closed_one(tmp_path):
    async def pages(session, base):
        return json.loads((await status(session, "GET", base + "/status.json"))[1])["pages"]

    async def check(session, base):
        assert await pages(session, base) == 0
        first = await session.ws_connect(base + "/ws")
        second = await session.ws_connect(base + "/ws")
        for ws in (first, second):
            assert (await ws.receive_json())["type"] == "hello"
        assert await pages(session, base) == 2
        await first.close()
        for _ in range(100):  # the server's side of the close runs on its loop
            if await pages(session, base) == 1:
                break
            await asyncio.sleep(0.01)
        assert await pages(session, base) == 1
        await second.close()
    serve(tmp_path, "", check)


def test_everything_needs_the_token_when_one_is_set(tmp_path):
    async def check(session, base):
        for path in ("/", "/views.json", "/status.json", "/ws", "/index.html?token=wrong"):
            assert (await status(session, "GET", base + path))[0] == 403, path
        with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
            await session.ws_connect(base + "/ws")
        assert refused.value.status == 403
        # with it in the URL, the page loads and its cookie lets its own requests in
        assert (await status(session, "GET", base + "/?token=s3cret"))[0] == 200
        assert (await status(session, "GET", base + "/views.json"))[0] == 200
        ws = await session.ws_connect(base + "/ws")
        assert (await ws.receive_json())["type"] == "hello"
        await ws.close()
    serve(tmp_path, "s3cret", check)


def test_bad_websocket_messages_get_clear_errors_and_the_server_stays_up(tmp_path):
    async def check(session, base):
        ws = await session.ws_connect(base + "/ws")
        hello = await ws.receive_json()
        assert hello["views"][0]["name"] == "echo"
        cases = [("{not json", "not JSON"), ("[1, 2]", "JSON object"), ('{"view": "echo"}', "JSON object"),
                 ('{"view": "nope", "type": "x"}', "no view named 'nope'"),
                 ('{"view": "echo", "type": "bad", "id": 3}', "field x: expected a number"),
                 ('{"view": "echo", "type": "fail", "id": 4}', "view echo failed: RuntimeError: a bug")]
        for text, expected in cases:
            await ws.send_str(text)
            reply = await ws.receive_json()
            assert reply["type"] == "error" and expected in reply["error"], (text, reply)
        await ws.send_bytes(b"\x00\x01")
        assert "binary" in (await ws.receive_json())["error"]
        await ws.send_str(json.dumps({"view": "echo", "type": "say", "id": 5, "text": "hi"}))
        assert await ws.receive_json() == {"view": "echo", "type": "say", "id": 5, "text": "hi"}
        # too big: the server closes this socket (1009) and serves the next one
        await ws.send_str("x" * (MAX_MESSAGE_BYTES + 10))
        closed = await ws.receive()
        assert closed.type in (aiohttp.WSMsgType.CLOSE, aiohttp.WSMsgType.CLOSED) and ws.close_code == 1009
        again = await session.ws_connect(base + "/ws")
        assert (await again.receive_json())["type"] == "hello"
        await again.close()
    serve(tmp_path, "", check)


def test_a_taken_port_is_reported_and_the_next_server_can_try_again(tmp_path):
    async def run():
        first = Studio("127.0.0.1", 0, "", {"": str(tmp_path)})
        await first.start()
        second = Studio("127.0.0.1", first.port, "", {"": str(tmp_path)})
        with pytest.raises(OSError):
            await second.start()
        second.port = 0
        await second.start()  # nothing left half-open by the failed try
        assert second.port not in (0, first.port)
        await second.stop()
        await first.stop()
    asyncio.run(run())


def test_an_unknown_view_name_is_refused_with_the_names_there_are():
    from sim_studio.registry import load_views, view_folders
    with pytest.raises(ValueError) as refused:
        load_views(None, ["world", "wrold"])
    assert "no view named wrold" in str(refused.value) and "world" in str(refused.value).split("there are:")[1]
    assert {"world", "models", "joints", "topics", "plot", "publisher", "graph", "images"} <= set(view_folders())
