"""Finds the views: every package under sim_studio/views/ with a `VIEW` class. Adding a view is
adding a folder; nothing else lists them."""
import importlib
import os
import pkgutil

from sim_studio import views


def view_folders():
    """{name: folder} for every view package."""
    found = {}
    for path in views.__path__:
        for info in pkgutil.iter_modules([path]):
            if info.ispkg:
                found.setdefault(info.name, os.path.join(path, info.name))
    return found


def load_views(studio, only=None):
    """One instance of each view (or of those named in `only`), ordered by slot and order."""
    unknown = sorted(set(only or ()) - set(view_folders()))
    if unknown:
        raise ValueError("no view named %s (there are: %s)" % (", ".join(unknown), ", ".join(sorted(view_folders()))))
    made = []
    for name in sorted(view_folders()):
        if only and name not in only:
            continue
        module = importlib.import_module("sim_studio.views." + name)
        cls = getattr(module, "VIEW", None)
        if cls is None:
            raise ImportError("sim_studio/views/%s/__init__.py defines no VIEW class" % name)
        view = cls(studio)
        view.name = name
        made.append(view)
    return sorted(made, key=lambda v: (v.slot, v.order, v.name))
