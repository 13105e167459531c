"""The World view's pure parts: scene_info -> the page's scene (and the meshes it may serve),
poses at the page's pace and only what moved, the real-time factor."""
from geometry_msgs.msg import Pose
from visualization_msgs.msg import Marker

from sim_studio.views.world import scene
from sim_studio.views.world.pose_stream import PageFrames, PoseFrames
from sim_studio.views.world.sim_clock import RealTimeFactor


def marker(ns, frame, kind, text="", mesh="", scale=(1, 1, 1), action=Marker.ADD, x=0.0):
    m = Marker(ns=ns, type=kind, action=action, text=text, mesh_resource=mesh)
    m.header.frame_id = frame
    m.pose.position.x = x
    m.pose.orientation.w = 1.0
    m.scale.x, m.scale.y, m.scale.z = scale
    m.color.r, m.color.a = 1.0, 1.0
    return m


def test_scene_visuals_sensors_and_meshes(tmp_path):
    stl = tmp_path / "arm part.stl"
    stl.write_bytes(b"solid x\nendsolid x\n")
    old = marker("gone", "gone::link", Marker.CUBE)
    markers = [old, Marker(action=scene.DELETEALL),
               marker("arm", "arm::base", Marker.CYLINDER, "base", scale=(0.2, 0.2, 1.0), x=0.5),
               marker("arm", "arm::hand", Marker.MESH_RESOURCE, "hand", mesh="file://%s" % stl),
               marker("arm", "arm::hand", Marker.MESH_RESOURCE, "pic", mesh="file:///tmp/texture.png"),
               marker("arm", "arm::hand", Marker.MESH_RESOURCE, "web", mesh="http://example.com/x.stl"),
               marker("arm", "arm::hand", Marker.LINE_LIST, "laser:/arm/scan", scale=(30, 0, 0)),
               marker("arm", "arm::hand", Marker.LINE_LIST, "camera:/arm/image", scale=(100, 0, 0)),
               marker("arm", "arm::hand", Marker.TEXT_VIEW_FACING, "label")]
    found, meshes = scene.read_scene(markers)
    assert [v["name"] for v in found["visuals"]] == ["base", "hand"]  # before DELETEALL: dropped
    base, hand = found["visuals"]
    assert base["type"] == "cylinder" and base["frame"] == "arm::base" and base["scale"] == [0.2, 0.2, 1.0]
    assert base["pose"] == [0.5, 0, 0, 0, 0, 0, 1.0] and base["color"] == [1.0, 0, 0, 1.0]
    assert hand["format"] == "stl" and hand["mesh"].endswith("/arm%20part.stl")
    assert meshes == {scene.mesh_id(str(stl)): str(stl)}  # only the loadable file:// mesh
    assert hand["mesh"] == "/api/world/mesh/%s/arm%%20part.stl" % scene.mesh_id(str(stl))
    assert [(s["kind"], s["topic"], s["range"]) for s in found["sensors"]] == [
        ("laser", "/arm/scan", 30.0), ("camera", "/arm/image", 100.0)]
    assert len(found["skipped"]) == 3  # the PNG, the http mesh, the text marker: said, not drawn


def test_mesh_path_takes_only_absolute_local_mesh_files():
    assert scene.mesh_path("file:///a/b/../c.DAE") == "/a/c.DAE"
    assert scene.mesh_path("file:///a/b%20c.obj") == "/a/b c.obj"
    for refused in ("file://host/a.stl", "package://p/a.stl", "file:a.stl", "/a.stl", "file:///a.ply", ""):
        assert scene.mesh_path(refused) is None, refused


def poses(*xs):
    out = []
    for x in xs:
        p = Pose()
        p.position.x = x
        p.orientation.w = 1.0
        out.append(p)
    return out


def test_a_page_gets_names_once_then_only_what_moved():
    frames, page = PoseFrames(), PageFrames()
    assert page.waiting and page.next_frame(frames) is None  # nothing yet
    frames.update(["a::l", "b::l"], poses(1.0, 2.0))
    first = page.next_frame(frames)
    assert first["names"] == ["a::l", "b::l"]
    assert first["poses"] == [0, 1.0, 0, 0, 0, 0, 0, 1.0, 1, 2.0, 0, 0, 0, 0, 0, 1.0]
    frames.update(["a::l", "b::l"], poses(1.0, 2.5))
    frames.update(["a::l", "b::l"], poses(1.0, 3.0))  # the page was slow: it gets the newest
    assert page.next_frame(frames) == {"seq": 3, "poses": [1, 3.0, 0, 0, 0, 0, 0, 1.0]}
    frames.update(["a::l", "b::l"], poses(1.00004, 3.0))  # below a tenth of a millimetre
    assert page.next_frame(frames) is None
    frames.update(["b::l"], poses(3.0))  # a model went: names again, every pose
    assert page.next_frame(frames) == {"seq": 5, "names": ["b::l"], "poses": [0, 3.0, 0, 0, 0, 0, 0, 1.0]}
    other = PageFrames()  # a second page starts from everything
    assert other.next_frame(frames)["names"] == ["b::l"]


def test_real_time_factor_over_the_last_second():
    rtf = RealTimeFactor(window=1.0)
    assert rtf.add(0.0, 10.0) is None
    assert abs(rtf.add(0.5, 11.0) - 2.0) < 1e-9
    for i in range(2, 9):
        value = rtf.add(i * 0.5, 10.0 + i * 0.5)  # now real time
    assert abs(value - 1.0) < 1e-9
    rtf.add(5.0, 0.0)  # reset_simulation: starts over
    assert abs(rtf.add(5.5, 0.25) - 0.5) < 1e-9
