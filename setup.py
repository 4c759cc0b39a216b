"""Builds the Python package cmx with CMake (pyproject.toml says how to call it).

The extension cmx._cmx is the CMake target cmx_python (python/CMakeLists.txt); this script
configures the project with -DCMX_PYTHON=ON -DCMX_BUILD_TESTS=OFF -DCMX_BUILD_CLI=OFF for the
running interpreter, builds that target and copies the extension into the wheel beside the
package's pure-Python files (python/cmx). The CMake build folder is CMX_BUILD_DIR when set, else
setuptools' build_temp.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.egg_info import egg_info

ROOT = Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    m = re.search(r"project\(\s*cmx\s+VERSION\s+([0-9][0-9.]*)", text)
    if not m:
        raise RuntimeError("setup.py: no project(cmx VERSION ...) in CMakeLists.txt")
    return m.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = Path(os.environ.get("CMX_BUILD_DIR") or Path(self.build_temp).resolve() / "cmake")
        build_dir.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release", "-DCMX_PYTHON=ON", "-DCMX_BUILD_TESTS=OFF", "-DCMX_BUILD_CLI=OFF",
            f"-DPYTHON_EXECUTABLE={sys.executable}",
        ]
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "cmx_python", "-j", jobs], check=True)
        built = sorted((build_dir / "python" / "cmx").glob("_cmx*.so"))
        if not built:
            raise RuntimeError(f"setup.py: no _cmx extension under {build_dir / 'python' / 'cmx'}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[-1], target)


class EggInfo(egg_info):
    """Keeps the .egg-info folder out of the source tree (under build/)."""

    def initialize_options(self):
        super().initialize_options()
        self.egg_base = os.path.relpath(ROOT / "build" / "python-egg-info", os.getcwd())
        os.makedirs(self.egg_base, exist_ok=True)


setup(
    version=project_version(),
    packages=["cmx"],
    package_dir={"": "python"},
    ext_modules=[Extension("cmx._cmx", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "egg_info": EggInfo},
    zip_safe=False,
)
