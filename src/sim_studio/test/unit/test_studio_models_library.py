"""The Models view's pure parts: the model folders and the models in them, names for copies,
and the simple shapes' SDF."""
import xml.etree.ElementTree as ET

import pytest

from sim_studio.views.models import model_library, primitives


def make_model(folder, name, config_name=None, sdf_name="model.sdf", with_sdf=True):
    path = folder / name
    path.mkdir(parents=True)
    sdf = "<sdf>%s</sdf>" % sdf_name if sdf_name != "model.sdf" else ""
    (path / "model.config").write_text("<model><name>%s</name>%s<description> a  model </description></model>"
                                       % (config_name or name, sdf))
    if with_sdf:
        (path / sdf_name).write_text("<sdf version='1.6'><model name='%s'/></sdf>" % name)
    return path


def test_folders_in_gazebo_order(tmp_path):
    env, home, pkg = tmp_path / "env", tmp_path / "home", tmp_path / "pkg"
    for folder in (env, home / ".gazebo" / "models", pkg / "models"):
        folder.mkdir(parents=True)
    found = model_library.model_folders("%s:%s:/no/such" % (env, env), str(home), [str(pkg), str(tmp_path / "none")])
    assert found == [str(env), str(home / ".gazebo" / "models"), str(pkg / "models")]


def test_models_found_first_wins_and_broken_ones_skipped(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    make_model(a, "maze", config_name="The Maze")
    make_model(a, "robot", sdf_name="robot-1.6.sdf")
    make_model(a, "no_sdf", with_sdf=False)
    (a / "not_a_model").mkdir()
    (a / "bad_config").mkdir()
    (a / "bad_config" / "model.config").write_text("<model>")
    make_model(b, "maze", config_name="Another maze")
    models = model_library.find_models([str(a), str(b)])
    assert [(m["name"], m["folder"]) for m in models] == [("The Maze", str(a / "maze")), ("robot", str(a / "robot"))]
    assert models[0]["description"] == "a model"
    assert models[1]["sdf"].endswith("robot-1.6.sdf")
    assert "model name='robot'" in model_library.read_sdf(models[1])
    with pytest.raises(ValueError, match="cannot read"):
        model_library.read_sdf({"sdf": str(a / "gone.sdf")})


def test_unique_names_as_gazebo_gives_them():
    assert model_library.unique_name("unit_box", {"arm"}) == "unit_box"
    assert model_library.unique_name("unit_box", {"unit_box"}) == "unit_box_0"
    assert model_library.unique_name("unit_box", {"unit_box", "unit_box_0"}) == "unit_box_1"


@pytest.mark.parametrize("shape,ixx,izz", [("box", 1 / 6, 1 / 6), ("sphere", 0.1, 0.1), ("cylinder", 1.75 / 12, 0.125)])
def test_shapes_are_unit_solids_of_one_kilogram(shape, ixx, izz):
    root = ET.fromstring(primitives.shape_sdf(shape, "unit_" + shape))
    assert root.find("model").get("name") == "unit_" + shape
    assert float(root.find("model/link/inertial/mass").text) == 1.0
    assert abs(float(root.find("model/link/inertial/inertia/ixx").text) - ixx) < 1e-6
    assert abs(float(root.find("model/link/inertial/inertia/izz").text) - izz) < 1e-6
    assert root.find("model/link/visual/geometry/" + shape) is not None
    assert primitives.resting_height(shape) == 0.5
    with pytest.raises(ValueError, match="shape: expected one of box, sphere, cylinder, got 'cone'"):
        primitives.shape_sdf("cone", "x")
