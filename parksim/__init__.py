"""Not the Python module: this folder holds the C++ sources of the parksim library.

Python started in the repository's top folder finds this folder first under the name `parksim`
(the current directory comes first on its path). So that `import parksim` there means the
Python module, this file loads the module in its place: the built one when the path has it
(PYTHONPATH=build/python), else the sources in python/parksim/, whose import then fails with
one line saying how to build the compiled part.
"""

import importlib.util as _util
import os as _os
import sys as _sys


def _package_dir():
    """The folder of the Python package `parksim`: the first one on sys.path that is not this
    folder, else python/parksim/ of this repository."""
    here = _os.path.dirname(_os.path.abspath(__file__))
    for entry in _sys.path:
        folder = _os.path.join(_os.path.abspath(entry or _os.curdir), "parksim")
        if folder != here and _os.path.isfile(_os.path.join(folder, "__init__.py")):
            return folder
    return _os.path.join(_os.path.dirname(here), "python", "parksim")


def _load_in_place():
    folder = _package_dir()
    spec = _util.spec_from_file_location("parksim", _os.path.join(folder, "__init__.py"),
                                         submodule_search_locations=[folder])
    module = _util.module_from_spec(spec)
    # The import statement returns what sys.modules holds once this file has run.
    _sys.modules["parksim"] = module
    spec.loader.exec_module(module)


_load_in_place()
