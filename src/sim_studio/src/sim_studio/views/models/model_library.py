"""The models a user can insert, as Gazebo's Insert tab lists them: every folder holding a
model.config and its SDF file, under GAZEBO_MODEL_PATH, ~/.gazebo/models and every package's
models/ folder, searched in that order (the simulator's own order for model:// URIs, so the
first of two models with one name is the one model://NAME finds). Pure functions, no ROS."""
import os
import xml.etree.ElementTree as ET

MAX_SDF_BYTES = 4 << 20  # a model.sdf is text; anything larger is not one


def model_folders(gazebo_model_path, home, package_folders):
    """The folders to search: GAZEBO_MODEL_PATH's entries, ~/.gazebo/models, then each package's
    models/ folder; only those that exist, each once."""
    candidates = [p for p in (gazebo_model_path or "").split(os.pathsep) if p]
    if home:
        candidates.append(os.path.join(home, ".gazebo", "models"))
    candidates += [os.path.join(p, "models") for p in package_folders]
    found = []
    for folder in candidates:
        folder = os.path.abspath(folder)
        if os.path.isdir(folder) and folder not in found:
            found.append(folder)
    return found


def read_model_config(folder):
    """(name, sdf file, description) from folder/model.config, or None when the folder is not a
    model: no model.config, unreadable XML, or no SDF file beside it. The SDF file is the one
    model.config names (<sdf>), else model.sdf."""
    config = os.path.join(folder, "model.config")
    if not os.path.isfile(config):
        return None
    try:
        root = ET.parse(config).getroot()
    except (ET.ParseError, OSError):
        return None
    named = [e.text.strip() for e in root.findall("sdf") if e.text and e.text.strip()]
    sdf = next((os.path.join(folder, n) for n in named + ["model.sdf"]
                if os.path.isfile(os.path.join(folder, n))), None)
    if sdf is None:
        return None
    name = (root.findtext("name") or "").strip() or os.path.basename(folder)
    description = " ".join((root.findtext("description") or "").split())
    return name, sdf, description


def find_models(folders):
    """[{"key", "name", "folder", "sdf", "description"}] for every model folder directly under
    `folders`, in search order; a model name found twice is listed once (the first), as
    model:// resolves it. `key` is what a page sends back to insert it."""
    models, seen = [], set()
    for folder in folders:
        try:
            entries = sorted(os.listdir(folder))
        except OSError:
            continue
        for entry in entries:
            path = os.path.join(folder, entry)
            if entry in seen or not os.path.isdir(path):
                continue
            config = read_model_config(path)
            if config is None:
                continue
            seen.add(entry)
            name, sdf, description = config
            models.append({"key": path, "name": name, "folder": path, "sdf": sdf, "description": description})
    return models


def read_sdf(model):
    """The SDF text of a model found by find_models; ValueError when it cannot be read."""
    try:
        if os.path.getsize(model["sdf"]) > MAX_SDF_BYTES:
            raise ValueError("%s is larger than %d MB; not an SDF model" % (model["sdf"], MAX_SDF_BYTES >> 20))
        with open(model["sdf"], encoding="utf-8") as f:
            return f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise ValueError("cannot read %s: %s" % (model["sdf"], e)) from None


def unique_name(base, taken):
    """Gazebo's names for a second copy: base, then base_0, base_1, ..."""
    if base not in taken:
        return base
    i = 0
    while "%s_%d" % (base, i) in taken:
        i += 1
    return "%s_%d" % (base, i)
