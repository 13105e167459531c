"""The World view's mesh route on a real socket, without ROS: a mesh the scene names is served,
anything else (another id, a path, ../) is 404, and the token guards it as every request."""
import asyncio

import aiohttp
import yarl

from sim_studio.server import Studio
from sim_studio.views.world import WorldView, scene


def test_only_the_scene_meshes_are_served(tmp_path):
    mesh = tmp_path / "part.stl"
    mesh.write_bytes(b"solid part\nendsolid part\n")
    secret = tmp_path / "secret.stl"
    secret.write_bytes(b"secret")
    www = tmp_path / "www"
    www.mkdir()

    async def run():
        studio = Studio("127.0.0.1", 0, "tok", {"": str(www)})
        view = WorldView(studio)
        view.name = "world"
        view._meshes = {scene.mesh_id(str(mesh)): str(mesh)}
        studio.add_views([view])
        await studio.start()
        base = "http://127.0.0.1:%d" % studio.port
        try:
            async with aiohttp.ClientSession() as session:
                async def get(path, token="tok"):
                    url = yarl.URL(base + path + ("?token=" + token if token else ""), encoded=True)
                    async with session.get(url) as response:
                        return response.status, await response.read()
                good = "/api/world/mesh/%s/part.stl" % scene.mesh_id(str(mesh))
                assert await get(good) == (200, mesh.read_bytes())
                assert (await get(good, token=""))[0] == 403
                assert (await get("/api/world/mesh/%s/secret.stl" % scene.mesh_id(str(secret))))[0] == 404
                assert (await get("/api/world/mesh/../../%s" % secret))[0] == 404
                assert (await get("/api/world/mesh/%2e%2e/secret.stl"))[0] == 404
                mesh.unlink()  # named by the scene but gone from the disk
                assert (await get(good))[0] == 404
        finally:
            await studio.stop()
    asyncio.run(run())
