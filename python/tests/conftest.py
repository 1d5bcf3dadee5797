"""Fixtures of the Python module's tests: the module itself (PYTHONPATH=build/python) and the illum CLI
(ILLUM_CLI, which CTest sets; else build/illum beside the module's folder), whose results the module must
reproduce."""

import os
import pathlib
import subprocess

import pytest

import illum


def _cli_path():
    if os.environ.get("ILLUM_CLI"):
        return pathlib.Path(os.environ["ILLUM_CLI"])
    return pathlib.Path(illum.__file__).resolve().parent.parent / "illum"


@pytest.fixture(scope="session")
def cli():
    """run(*args, cwd=None) runs the illum CLI and returns the CompletedProcess (text output)."""
    path = _cli_path()
    if not path.exists():
        if os.environ.get("ILLUM_CLI"):
            pytest.fail(f"ILLUM_CLI={path} does not exist")
        pytest.skip(f"the illum CLI is not built ({path})")

    def run(*args, cwd=None):
        return subprocess.run([str(path), *map(str, args)], capture_output=True, text=True, cwd=cwd,
                              timeout=120)

    return run


# A small scene of our own: an area light, a coated (stochastic layered) sphere, a Ward sphere (a registry
# model used as a scene material), a floor and a constant environment; volpath as the scene's integrator.
SCENE = """LookAt 0 1.5 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [48] "integer yresolution" [32] "string filename" "unused.exr"
Sampler "zsobol" "integer pixelsamples" [8]
Integrator "volpath" "integer maxdepth" [5]
WorldBegin
LightSource "infinite" "rgb L" [0.2 0.25 0.3]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [6 6 6] "bool twosided" true
  Translate 0 3 0
  Rotate 90 1 0 0
  Shape "disk" "float radius" [1]
AttributeEnd
AttributeBegin
  Translate -0.6 0.5 0
  Material "coateddiffuse" "rgb reflectance" [0.7 0.3 0.2] "float roughness" [0.1]
  Shape "sphere" "float radius" [0.5]
AttributeEnd
AttributeBegin
  Translate 0.6 0.5 0
  Material "ward" "rgb rho_d" [0.2 0.3 0.5] "rgb rho_s" [0.3 0.3 0.3]
  Shape "sphere" "float radius" [0.5]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "point3 P" [-5 0 -5  5 0 -5  5 0 5  -5 0 5] "integer indices" [0 1 2 0 2 3]
"""


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "spheres.pbrt"
    path.write_text(SCENE)
    return path
