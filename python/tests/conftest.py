import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
ICOSA = DATA / "icosahedron_binary_le.ply"
OCTA = DATA / "octahedron.obj"
CUBE = ROOT / "examples" / "meshes" / "cube.obj"


def ppm(*args, check=False):
    """The crate's command line from the installed package (console script `ppm`)."""
    return subprocess.run(
        [sys.executable, "-m", "pseudomanifold._cli", *(a if isinstance(a, str) else os.fspath(a) if isinstance(a, os.PathLike) else str(a) for a in args)],
        capture_output=True,
        text=True,
        check=check,
    )


@pytest.fixture(scope="session")
def icosa():
    import pseudomanifold as pm

    return pm.load(ICOSA)


@pytest.fixture(scope="session")
def icosa_pps(icosa):
    return icosa.pps()
