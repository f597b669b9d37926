"""eulermap: the Eulerian Surface Map filter (a MeshLab plugin) for pymeshlab.

Importing the package checks that the installed pymeshlab is the one the plugin was built
against (the wheel pins it; MeshLab's loader would refuse the plugin otherwise) and loads
the plugin, libfilter_eulermap_2025.so beside this file, into pymeshlab once per process.

    import pymeshlab, eulermap
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh("sphere.ply")   # layer 0
    ms.load_new_mesh("torus.ply")    # layer 1
    figures = eulermap.map_meshes(ms, 0, 1, grid_resolution=48)
    # new layers: 2 sphere_cut, 3 sphere_mapped (4 sphere_filled with fill_holes=True)

map_meshes() takes the filter's parameters as keyword arguments (parameters() lists them
with their defaults) and returns the report's figures (a dict); a failure raises
pymeshlab.PyMeshLabException with the filter's message. map_files() does the whole job on
files, as the command `eulermap map` does.
"""
import importlib.metadata as _metadata
import os as _os
import re as _re

__all__ = ["FILTER", "PLUGIN", "PYMESHLAB_REQUIRED", "map_meshes", "map_files", "parameters", "progress_bar", "MapResult"]


def _required_pymeshlab():
    """The pymeshlab version this wheel requires, as its metadata states it (pyproject.toml)."""
    for requirement in _metadata.requires("eulermap") or []:
        m = _re.match(r"pymeshlab\s*==\s*([^\s;,]+)", requirement)
        if m:
            return m.group(1)
    raise ImportError("eulermap's metadata names no pymeshlab==VERSION requirement: reinstall eulermap")


PYMESHLAB_REQUIRED = _required_pymeshlab()
try:
    _found = _metadata.version("pymeshlab")
except _metadata.PackageNotFoundError:
    _found = None
if _found != PYMESHLAB_REQUIRED:
    raise ImportError(
        f"eulermap's plugin is built for pymeshlab=={PYMESHLAB_REQUIRED} (MeshLab 2025.07), and MeshLab "
        f"refuses a plugin built for another version; this environment has "
        f"{'no pymeshlab' if _found is None else 'pymeshlab ' + _found}. "
        f"Install the one it needs: pip install pymeshlab=={PYMESHLAB_REQUIRED}")

import pymeshlab as _pymeshlab  # noqa: E402  (only once the version is known to fit)

__version__ = _metadata.version("eulermap")
FILTER = "generate_eulerian_surface_map"
PLUGIN = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "libfilter_eulermap_2025.so")

if FILTER not in _pymeshlab.filter_list():  # a second load_plugin of the same file is an error
    if not _os.path.isfile(PLUGIN):
        raise ImportError(f"{PLUGIN} missing: the eulermap wheel is incomplete, reinstall it")
    _pymeshlab.load_plugin(PLUGIN)

from ._mapping import MapResult, map_files, map_meshes, parameters, progress_bar  # noqa: E402
